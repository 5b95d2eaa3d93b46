#include "viz/views.h"

#include "viz/diagram_surface.h"

#include <fmt/format.h>

namespace rayset::viz {

ViewHandles add_view(vtkRenderer* renderer, Input& input, View view, const ViewOptions& options) {
    auto data = input.data(view, options);
    const std::string title = input.label();
    switch (view) {
        case View::rays:
            return add_rays_view(renderer, vtkPolyData::SafeDownCast(data),
                                 title + ": ray origins and directions", options.colour_by_flux);
        case View::farfield:
            return add_farfield_view(renderer, vtkPolyData::SafeDownCast(data),
                                     title + ": photometric solid");
        case View::polar: return add_polar_view(renderer, {&input.intensity()});
        case View::density:
            return add_density_view(renderer, vtkImageData::SafeDownCast(data),
                                    title + ": density lattice", options.density_threshold,
                                    options.contour);
        case View::spheres:
            return add_spheres_view(renderer, vtkPolyData::SafeDownCast(data),
                                    title + ": boundary spheres");
        case View::flux:
            return add_flux_view(renderer, vtkImageData::SafeDownCast(data),
                                 title + ": flux lattice");
        case View::diagram: {
            const auto cell = chosen_cell(input.model(), options);
            return add_diagram_view(
                renderer, vtkPolyData::SafeDownCast(data),
                fmt::format("{}: goniometric diagram of intensity cell {},{},{}", title, cell[0],
                            cell[1], cell[2]));
        }
        case View::image: {
            const ExrLayer& layer = input.image(options.layer);
            return add_image_view(renderer, layer, title + ": " + layer.channel);
        }
    }
    return {};
}

}  // namespace rayset::viz
