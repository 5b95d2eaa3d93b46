// File writers of the film: OpenEXR with named float channels, 8-bit sRGB PNG, and the
// preview tone mapping.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "tracer/film/film.h"

namespace rayset::tracer {

struct ExrChannel {
    std::string name;
    std::vector<float> values;  // width * height, row by row from the top
};

// `attributes`: string attributes stored in the header (units, what the channels mean).
void write_exr(const std::string& path, int width, int height,
               const std::vector<ExrChannel>& channels,
               const std::vector<std::pair<std::string, std::string>>& attributes = {});

// 8-bit RGB, rows from the top, tagged sRGB.
void write_png(const std::string& path, int width, int height, const std::vector<uint8_t>& rgb);

// Preview: radiance times `exposure` (when <= 0, the reciprocal of the 99th percentile of the
// largest channel over the pixels that are not black); a pixel brighter than 1 in some channel
// is scaled down as a whole (hue kept); then the sRGB transfer function.
std::vector<uint8_t> tone_map_srgb(const Film& film, double exposure);

}  // namespace rayset::tracer
