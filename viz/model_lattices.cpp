#include "viz/model_lattices.h"

#include "viz/vtk_arrays.h"

#include <vtkCellArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>

namespace rayset::viz {

namespace {

vtkSmartPointer<vtkImageData> image_over(const lightmodel::LatticeFrame& frame) {
    auto image = vtkSmartPointer<vtkImageData>::New();
    const auto& d = frame.dims();
    image->SetDimensions(d[0], d[1], d[2]);
    const Vec3 c = frame.cell_centre({0, 0, 0});
    image->SetOrigin(c.x, c.y, c.z);
    image->SetSpacing(frame.cell_size(), frame.cell_size(), frame.cell_size());
    return image;
}

}  // namespace

vtkSmartPointer<vtkImageData> density_image(const lightmodel::LightModel& model) {
    auto image = image_over(model.density_frame);
    auto density = named_floats("density");
    density->SetNumberOfTuples(model.density_frame.cell_count());
    density->FillValue(0);
    // The frame's linear index (x fastest) is VTK's point order.
    for (size_t v = 0; v < model.voxels.size(); ++v)
        density->SetValue(model.density_frame.linear(model.voxels[v]), model.voxel_density[v]);
    image->GetPointData()->SetScalars(density);
    set_field_string(image, "unit", "rays");
    return image;
}

vtkSmartPointer<vtkImageData> flux_image(const lightmodel::LightModel& model) {
    auto image = image_over(model.flux_frame);
    auto flux = named_doubles("flux"), luminous = named_doubles("luminous");
    for (auto* a : {flux.Get(), luminous.Get()}) {
        a->SetNumberOfTuples(model.flux_frame.cell_count());
        a->FillValue(0);
    }
    for (const auto& cell : model.flux_cells) {
        const int64_t i = model.flux_frame.linear(cell.coord);
        flux->SetValue(i, cell.flux);
        luminous->SetValue(i, cell.luminous);
    }
    image->GetPointData()->SetScalars(flux);
    image->GetPointData()->AddArray(luminous);
    set_field_string(image, "unit", model.flux_unit);
    return image;
}

vtkSmartPointer<vtkPolyData> sphere_set(const lightmodel::LightModel& model) {
    auto points = vtkSmartPointer<vtkPoints>::New();
    auto radius = named_floats("radius");
    auto vertices = vtkSmartPointer<vtkCellArray>::New();
    for (const auto& s : model.spheres) {
        const vtkIdType id = points->InsertNextPoint(s.x, s.y, s.z);
        vertices->InsertNextCell(1, &id);
        radius->InsertNextValue(s.r);
    }
    auto spheres = vtkSmartPointer<vtkPolyData>::New();
    spheres->SetPoints(points);
    spheres->SetVerts(vertices);
    spheres->GetPointData()->SetScalars(radius);
    set_field_string(spheres, "unit", "mm");
    return spheres;
}

}  // namespace rayset::viz
