// The test image writer module (image_writing.h): OpenImageIO, loaded by the tests that write
// images, so that the other tests of the same binaries do not load its libraries at start.
#include <memory>
#include <string>
#include <type_traits>

#include <OpenImageIO/imageio.h>

#include "support/image_writing.h"

extern "C" __attribute__((visibility("default"))) bool rayset_test_write_image(
    const char* path, int width, int height, int channels, const float* values, bool floating,
    std::string& error) {
    std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(path);
    if (!out) {
        error = OIIO::geterror();
        return false;
    }
    const OIIO::ImageSpec spec(width, height, channels,
                               floating ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
    if (!out->open(path, spec) || !out->write_image(OIIO::TypeDesc::FLOAT, values) ||
        !out->close()) {
        error = out->geterror();
        return false;
    }
    return true;
}
static_assert(std::is_same_v<decltype(&rayset_test_write_image), rayset::test::WriteImageEntry>,
              "the entry point has the type image_writing.cpp calls it by");
