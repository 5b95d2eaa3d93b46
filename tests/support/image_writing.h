// Small images written by the tests that need them, so that no binary image lives in the
// repository: OpenImageIO, in a module loaded on the first image (image_writer_module.cpp).
#pragma once

#include <string>
#include <vector>

namespace rayset::test {

// Writes `values` (`channels` per pixel, rows from the top, in [0, 1] unless `floating`) in the
// format of the path's extension: 8 bits per channel, or 32-bit floats where the format
// holds them (`floating`: EXR, HDR). Throws std::runtime_error when it cannot.
void write_image(const std::string& path, int width, int height, int channels,
                 const std::vector<float>& values, bool floating = false);

// The writer module's entry point (image_writer_module.cpp), which write_image loads and calls.
using WriteImageEntry = bool (*)(const char* path, int width, int height, int channels,
                                 const float* values, bool floating, std::string& error);
inline constexpr const char* kWriteImageEntry = "rayset_test_write_image";

}  // namespace rayset::test
