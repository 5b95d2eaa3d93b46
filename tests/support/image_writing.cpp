#include "support/image_writing.h"

#include <memory>
#include <stdexcept>

#include <OpenImageIO/imageio.h>

namespace rayset::test {

void write_image(const std::string& path, int width, int height, int channels,
                 const std::vector<float>& values, bool floating) {
    std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(path);
    if (!out) throw std::runtime_error("cannot write " + path + ": " + OIIO::geterror());
    const OIIO::ImageSpec spec(width, height, channels,
                               floating ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
    if (values.size() != size_t(width) * size_t(height) * size_t(channels) ||
        !out->open(path, spec) || !out->write_image(OIIO::TypeDesc::FLOAT, values.data()) ||
        !out->close())
        throw std::runtime_error("cannot write " + path + ": " + out->geterror());
}

}  // namespace rayset::test
