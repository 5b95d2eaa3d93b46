#include "support/image_writing.h"

#include <dlfcn.h>

#include <stdexcept>

namespace rayset::test {
namespace {

// The writer module of this build (RAYSET_TEST_IMAGE_WRITER, its path), loaded on first use.
WriteImageEntry writer() {
    static const WriteImageEntry write = [] {
        void* module = dlopen(RAYSET_TEST_IMAGE_WRITER, RTLD_NOW | RTLD_LOCAL);
        return module ? reinterpret_cast<WriteImageEntry>(dlsym(module, kWriteImageEntry))
                      : nullptr;
    }();
    if (!write) throw std::runtime_error(std::string("cannot load ") + RAYSET_TEST_IMAGE_WRITER);
    return write;
}

}  // namespace

void write_image(const std::string& path, int width, int height, int channels,
                 const std::vector<float>& values, bool floating) {
    std::string error;
    if (values.size() != size_t(width) * size_t(height) * size_t(channels) ||
        !writer()(path.c_str(), width, height, channels, values.data(), floating, error))
        throw std::runtime_error("cannot write " + path + ": " + error);
}

}  // namespace rayset::test
