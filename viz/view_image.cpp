// Image view: one EXR layer colour-mapped by luminance (or illuminance), with its scale bar.
#include "viz/view_style.h"
#include "viz/views.h"

#include <vtkDataArray.h>
#include <vtkImageActor.h>
#include <vtkImageMapToColors.h>
#include <vtkImageMapper3D.h>
#include <vtkPointData.h>

namespace rayset::viz {

ViewHandles add_image_view(vtkRenderer* renderer, const ExrLayer& layer, const std::string& title) {
    double range[2];
    layer.image->GetPointData()->GetScalars()->GetRange(range);
    auto lut = colour_map(range[0], range[1]);
    auto colours = vtkSmartPointer<vtkImageMapToColors>::New();
    colours->SetInputData(layer.image);
    colours->SetLookupTable(lut);
    colours->SetOutputFormatToRGB();
    auto actor = vtkSmartPointer<vtkImageActor>::New();
    actor->GetMapper()->SetInputConnection(colours->GetOutputPort());
    renderer->AddActor(actor);
    const bool illuminance = layer.unit == "lux" || layer.unit == "lx";
    add_scalar_bar(
        renderer, lut,
        std::string(illuminance ? "illuminance" : "luminance") + " (" + layer.unit + ")");
    add_title(renderer, title);
    ViewHandles h;
    h.flat = true;
    return h;
}

}  // namespace rayset::viz
