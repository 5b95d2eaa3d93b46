#include "tracer/tracer_support.h"

#include <cmath>
#include <cstdio>

#include "tracer/render/rgb.h"

namespace rayset::test {

std::string closed_box_scene(const ClosedBox& box) {
    char head[256];
    std::snprintf(head, sizeof head,
                  "global_settings { integrator \"bidirectional\" spectral %s }\n"
                  "box { <-50, -50, -50>, <50, 50, 50> pigment { rgb %s } finish { diffuse %.17g "
                  "ambient 0 } }\n",
                  box.spectral ? "on" : "off", box.pigment.c_str(), box.diffuse);
    std::string text = head;
    // corner, edge1, edge2 with cross(edge1, edge2) pointing into the box
    const char* const walls[][4] = {{"floor", "<-50, -50, -50>", "<0, 0, 100>", "<100, 0, 0>"},
                                    {"ceiling", "<-50, 50, -50>", "<100, 0, 0>", "<0, 0, 100>"},
                                    {"left", "<-50, -50, -50>", "<0, 100, 0>", "<0, 0, 100>"},
                                    {"right", "<50, -50, -50>", "<0, 0, 100>", "<0, 100, 0>"},
                                    {"near", "<-50, -50, -50>", "<100, 0, 0>", "<0, 100, 0>"},
                                    {"far", "<-50, -50, 50>", "<0, 100, 0>", "<100, 0, 0>"}};
    const std::string cells = std::to_string(box.cells);
    for (const auto& w : walls)
        text += std::string("illuminance_receiver { ") + w[1] + ", " + w[2] + ", " + w[3] +
                " resolution <" + cells + ", " + cells + "> name \"" + w[0] + "\" }\n";
    for (const std::string& s : box.sources)
        text += "ray_source { \"" + s + "\" rotate <90, 0, 0> }\n";
    return text;
}

WallAverage wall_average(const std::vector<tracer::ReceiverMap>& maps) {
    double sum = 0, squares = 0;
    int cells = 0;
    for (const tracer::ReceiverMap& map : maps)
        for (int j = 0; j < map.irradiance.ny(); ++j)
            for (int i = 0; i < map.irradiance.nx(); ++i) {
                sum += tracer::luminance_weight(map.irradiance.mean(i, j));
                const double se =
                    map.irradiance.photometric_standard_error(i, j) / tracer::kLumensPerWatt;
                squares += se * se, ++cells;
            }
    return {sum / cells, std::sqrt(squares) / cells};
}

}  // namespace rayset::test
