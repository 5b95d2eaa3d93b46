#include "viz/input.h"

#include "converters/photometry/photometry.h"
#include "converters/rays/ray_stream.h"
#include "core/error.h"
#include "lightmodel/model_file.h"
#include "viz/diagram_surface.h"
#include "viz/model_lattices.h"
#include "viz/photometric_solid.h"
#include "viz/polar_curves.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace rayset::viz {

namespace {

constexpr const char* kViewNames[] = {"rays",    "farfield", "polar",   "density",
                                      "spheres", "flux",     "diagram", "image"};

std::string lower_extension(const std::string& path) {
    std::string e = std::filesystem::path(path).extension().string();
    std::transform(e.begin(), e.end(), e.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return e;
}

InputKind detect_kind(const std::string& path) {
    if (!std::filesystem::is_regular_file(path)) throw Error(path + ": no such file");
    const std::string e = lower_extension(path);
    if (e == ".vdb") return InputKind::model;
    if (e == ".exr") return InputKind::image;
    try {
        detect_photometry_format(path);
        return InputKind::photometry;
    } catch (const Error&) {
    }
    try {
        detect_ray_format(path);
        return InputKind::rays;
    } catch (const Error&) {
    }
    throw Error(
        path +
        ": not a ray file, a model (.vdb), an IES / EULUMDAT file or an OpenEXR image (.exr)");
}

}  // namespace

const char* to_string(View view) { return kViewNames[int(view)]; }

std::optional<View> view_from_name(const std::string& name) {
    for (int v = 0; v < int(std::size(kViewNames)); ++v)
        if (name == kViewNames[v]) return View(v);
    return std::nullopt;
}

std::vector<View> views_of(InputKind kind) {
    switch (kind) {
        case InputKind::rays: return {View::rays, View::farfield, View::polar};
        case InputKind::model: return {View::spheres, View::density, View::flux, View::diagram};
        case InputKind::photometry: return {View::farfield, View::polar};
        case InputKind::image: return {View::image};
    }
    return {};
}

lightmodel::Coord chosen_cell(const lightmodel::LightModel& model, const ViewOptions& options) {
    return options.cell[0] < 0 ? brightest_intensity_cell(model) : options.cell;
}

Input::Input(std::string path) : path_(std::move(path)), kind_(detect_kind(path_)) {}

std::string Input::label() const { return std::filesystem::path(path_).filename().string(); }

const lightmodel::LightModel& Input::model() {
    if (kind_ != InputKind::model) throw Error(path_ + ": not a model (.vdb)");
    if (!model_) model_ = std::make_shared<lightmodel::LightModel>(lightmodel::read_model(path_));
    return *model_;
}

const IntensityTable& Input::intensity() {
    if (!intensity_) {
        if (kind_ == InputKind::rays) {
            FarFieldOptions smoothed;  // as rayconv farfield makes them by default
            smoothed.smoothing = FarFieldSmoothing::automatic;
            intensity_ = intensity_of_rays(path_, smoothed);
        } else if (kind_ == InputKind::photometry)
            intensity_ = intensity_of_photometry(path_);
        else
            throw Error(path_ + ": has no far field (open a ray file or an IES / EULUMDAT file)");
    }
    return *intensity_;
}

const ExrLayer& Input::image(const std::string& layer) {
    if (kind_ != InputKind::image) throw Error(path_ + ": not an OpenEXR image");
    if (!image_ || image_layer_ != layer) {
        image_ = read_exr_layer(path_, layer);
        image_layer_ = layer;
    }
    return *image_;
}

vtkSmartPointer<vtkPolyData> Input::rays(const RayCloudOptions& options) {
    if (kind_ != InputKind::rays) throw Error(path_ + ": not a ray file");
    return ray_cloud(path_, options);
}

vtkSmartPointer<vtkDataObject> Input::data(View view, const ViewOptions& options) {
    const auto offered = views_of(kind_);
    if (std::find(offered.begin(), offered.end(), view) == offered.end()) {
        std::string names;
        for (View v : offered) names += std::string(" ") + to_string(v);
        throw Error(path_ + ": no view '" + to_string(view) +
                    "' for this kind of file (views:" + names + ")");
    }
    switch (view) {
        case View::rays: return rays(options.rays);
        case View::farfield: return photometric_solid(intensity());
        case View::polar: return polar_curves(intensity());
        case View::density: return density_image(model());
        case View::spheres: return sphere_set(model());
        case View::flux: return flux_image(model());
        case View::diagram: return diagram_surface(model(), chosen_cell(model(), options));
        case View::image: return image(options.layer).image;
    }
    return nullptr;
}

}  // namespace rayset::viz
