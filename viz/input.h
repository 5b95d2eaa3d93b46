// What rayview opens: a ray file, a model (.vdb), an IES / EULUMDAT file or an EXR image, the
// views each kind offers, and the dataset behind each view (what is drawn and what --export
// writes). Files are read lazily and once.
#pragma once

#include "lightmodel/model.h"
#include "viz/exr_image.h"
#include "viz/intensity_table.h"
#include "viz/ray_cloud.h"

#include <vtkDataObject.h>
#include <vtkSmartPointer.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rayset::viz {

enum class InputKind { rays, model, photometry, image };
enum class View { rays, farfield, polar, density, spheres, flux, diagram, image };

const char* to_string(View view);
std::optional<View> view_from_name(const std::string& name);
// The views a kind of file offers; the first is shown when none is asked for.
std::vector<View> views_of(InputKind kind);

struct ViewOptions {
    lightmodel::Coord cell{-1, -1, -1};  // diagram: intensity cell; -1: the brightest
    std::string layer = "Y";             // image: channel or layer
    double density_threshold = 1;        // density: rays per voxel drawn (voxels) or contoured
    bool contour = false;                // density: contour surface instead of voxels
    bool colour_by_flux = false;         // rays: colour by flux even when wavelengths are known
    RayCloudOptions rays;
};

class Input {
public:
    // Detects the kind from the extension (.vdb, .exr) or the content (photometry, then rays);
    // throws rayset::Error when nothing fits.
    explicit Input(std::string path);

    const std::string& path() const { return path_; }
    InputKind kind() const { return kind_; }
    std::string label() const;  // file name

    const lightmodel::LightModel& model();
    const IntensityTable& intensity();
    const ExrLayer& image(const std::string& layer);
    vtkSmartPointer<vtkPolyData> rays(const RayCloudOptions& options);

    // The dataset of `view`; throws rayset::Error when this kind of file has no such view.
    vtkSmartPointer<vtkDataObject> data(View view, const ViewOptions& options);

private:
    std::string path_;
    InputKind kind_;
    std::shared_ptr<lightmodel::LightModel> model_;
    std::optional<IntensityTable> intensity_;
    std::optional<ExrLayer> image_;
    std::string image_layer_;
};

// The diagram cell `options` asks for, or the brightest one.
lightmodel::Coord chosen_cell(const lightmodel::LightModel& model, const ViewOptions& options);

}  // namespace rayset::viz
