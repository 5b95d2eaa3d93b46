#include "viz/ray_cloud.h"

#include "converters/rays/ray_stream.h"
#include "core/random.h"
#include "viz/vtk_arrays.h"

#include <vtkCellArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>

#include <vector>

namespace rayset::viz {

vtkSmartPointer<vtkPolyData> ray_cloud(const std::string& path, const RayCloudOptions& options) {
    auto reader = open_rays(path);
    const RayHeader& header = reader->header();
    Pcg32 rng(options.seed);
    std::vector<Ray> sample;
    sample.reserve(options.max_rays);
    uint64_t seen = 0;
    RayChunk chunk;
    while (reader->read(chunk))
        for (const Ray& ray : chunk.rays) {
            ++seen;
            if (sample.size() < options.max_rays) {
                sample.push_back(ray);
            } else {
                // Algorithm R: ray number `seen` replaces a kept one with probability max / seen.
                const uint64_t slot = uint64_t(rng.uniform() * double(seen));
                if (slot < options.max_rays) sample[slot] = ray;
            }
        }

    const bool radiant = header.has_radiant;
    auto points = vtkSmartPointer<vtkPoints>::New();
    auto vertices = vtkSmartPointer<vtkCellArray>::New();
    auto flux = named_floats("flux"), wavelength = named_floats("wavelength"),
         direction = named_floats("direction", 3);
    for (const Ray& ray : sample) {
        const vtkIdType id = points->InsertNextPoint(ray.origin.x, ray.origin.y, ray.origin.z);
        vertices->InsertNextCell(1, &id);
        flux->InsertNextValue(radiant ? ray.radiant : ray.luminous);
        const float nm = header.spectral == SpectralKind::single_wavelength
                             ? header.single_wavelength
                             : ray.wavelength;
        wavelength->InsertNextValue(nm);
        direction->InsertNextTuple3(ray.direction.x, ray.direction.y, ray.direction.z);
    }
    auto cloud = vtkSmartPointer<vtkPolyData>::New();
    cloud->SetPoints(points);
    cloud->SetVerts(vertices);
    cloud->GetPointData()->AddArray(flux);
    cloud->GetPointData()->AddArray(wavelength);
    cloud->GetPointData()->SetVectors(direction);
    set_field_string(cloud, "unit", to_string(header.unit));
    set_field_string(cloud, "flux_unit", radiant ? "W" : "lm");
    set_field_values(cloud, "rays", {double(seen)});
    return cloud;
}

}  // namespace rayset::viz
