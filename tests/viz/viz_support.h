// Shared by the viz tests: the synthetic 39-chip cluster's model written to a .vdb once per test
// binary, and pixel checks of rendered PNGs.
#pragma once

#include "lightmodel/model_support.h"

#include <string>

namespace rayset::test {

// The cluster of tests/lightmodel/model_support.h (1e6 rays, seed 7, 1 W) as a model file.
const std::string& cluster_model_file();

// Pixels of a PNG that differ from its top-left corner (the background).
struct PngStatistics {
    int width = 0, height = 0;
    long foreground = 0;  // whole image
    long region_foreground = 0;
    int region_colours = 0;  // distinct colours in the region
};
// `region` in fractions of the image: x0, x1, y0, y1 with y from the bottom.
PngStatistics png_statistics(const std::string& path, const double region[4]);

}  // namespace rayset::test
