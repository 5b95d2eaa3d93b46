// Everything a render writes, staged and committed together: the image as OpenEXR (linear
// R, G, B radiance in W/(m^2 sr) and Y luminance in cd/m^2), its PNG preview, and for each
// illuminance receiver an OpenEXR and a CSV map (irradiance in W/m^2, illuminance in lux).
#pragma once

#include <string>
#include <vector>

#include "tracer/film/film.h"

namespace rayset::tracer {

struct OutputRequest {
    std::string exr;              // image; empty: no image files
    std::string png;              // preview; empty: none
    double exposure = 0;          // preview exposure; <= 0: automatic (image_writers.h)
    std::string receiver_prefix;  // receiver maps go to PREFIX.NAME.exr and PREFIX.NAME.csv
};

// Returns the paths written. Throws rayset::Error, leaving no file behind, if any write fails.
std::vector<std::string> write_render_outputs(const Film* film,
                                              const std::vector<ReceiverMap>& receivers,
                                              const OutputRequest& request);

// The CSV text of a receiver map: one row per cell (see tracer/render/README.md).
std::string receiver_csv(const ReceiverMap& map);

}  // namespace rayset::tracer
