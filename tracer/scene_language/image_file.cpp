// Image files read through the image reader module (image_file.h, image_reader_module.h).
#include "tracer/scene_language/image_file.h"

#include <dlfcn.h>
#include <unistd.h>

#include <cmath>
#include <csetjmp>
#include <cstddef>
#include <cstdio>
#include <fstream>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <png.h>

#include "core/colour.h"
#include "core/error.h"
#include "tracer/scene_language/image_reader_module.h"

namespace rayset::tracer {
namespace {

// PNG keeps its colour type in the header (byte 25); 3 is a palette. OpenImageIO expands
// palettes to colours, so the indices POV-Ray reads from them (height fields, palette filter
// and transmit) are read here with libpng.
bool png_has_palette(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    char header[26] = {};
    if (!in.read(header, sizeof header)) return false;
    return std::string(header + 1, 3) == "PNG" && header[25] == 3;
}

// libpng reports errors by longjmp: no C++ object is made between setjmp and the end.
bool read_png_indices(std::FILE* file, int width, int height, uint8_t* indices) {
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    if (!png) return false;
    png_infop info = png_create_info_struct(png);
    if (!info || setjmp(png_jmpbuf(png))) {
        png_destroy_read_struct(&png, &info, nullptr);
        return false;
    }
    png_init_io(png, file);
    png_read_info(png, info);
    if (png_get_color_type(png, info) != PNG_COLOR_TYPE_PALETTE ||
        png_get_image_width(png, info) != png_uint_32(width) ||
        png_get_image_height(png, info) != png_uint_32(height)) {
        png_destroy_read_struct(&png, &info, nullptr);
        return false;
    }
    png_set_packing(png);  // 1, 2 and 4-bit indices one per byte
    const int passes = png_set_interlace_handling(png);
    png_read_update_info(png, info);
    for (int pass = 0; pass < passes; ++pass)
        for (int y = 0; y < height; ++y)
            png_read_row(png, indices + size_t(y) * size_t(width), nullptr);
    png_destroy_read_struct(&png, &info, nullptr);
    return true;
}

// Whether libpng decodes the whole file. OpenImageIO 2.4 loses memory when libpng fails inside
// its read callback (a file cut short): such files are refused before it reads them.
bool png_decodes(std::FILE* file) {
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    if (!png) return false;
    png_infop info = png_create_info_struct(png);
    png_bytep volatile row = nullptr;  // volatile: set after setjmp, freed after longjmp
    if (!info || setjmp(png_jmpbuf(png))) {
        png_free(png, row);
        png_destroy_read_struct(&png, &info, nullptr);
        return false;
    }
    png_init_io(png, file);
    png_read_info(png, info);
    const int passes = png_set_interlace_handling(png);
    png_read_update_info(png, info);
    row = static_cast<png_bytep>(png_malloc(png, png_get_rowbytes(png, info)));
    const png_uint_32 height = png_get_image_height(png, info);
    for (int pass = 0; pass < passes; ++pass)
        for (png_uint_32 y = 0; y < height; ++y) png_read_row(png, row, nullptr);
    png_read_end(png, nullptr);
    png_free(png, row);
    png_destroy_read_struct(&png, &info, nullptr);
    return true;
}

bool is_damaged_png(const std::string& path) {
    std::FILE* file = std::fopen(path.c_str(), "rb");
    if (!file) return false;
    unsigned char magic[8] = {};
    const bool png = std::fread(magic, 1, 8, file) == 8 && png_sig_cmp(magic, 0, 8) == 0;
    std::rewind(file);
    const bool damaged = png && !png_decodes(file);
    std::fclose(file);
    return damaged;
}

void read_palette_indices(const std::string& path, ImagePixels& pixels) {
    std::FILE* file = std::fopen(path.c_str(), "rb");
    if (!file) return;
    pixels.indices.resize(size_t(pixels.width) * size_t(pixels.height));
    if (!read_png_indices(file, pixels.width, pixels.height, pixels.indices.data()))
        pixels.indices.clear();
    std::fclose(file);
}

// The search path of the binary holding this code (its run path with $ORIGIN expanded, then the
// system's folders), as dlopen would search it when this code calls it. dlopen(name) itself is
// not used: a sanitizer runtime that intercepts dlopen (GCC's AddressSanitizer) becomes the
// caller whose run path it searches.
std::vector<std::string> own_search_path() {
    Dl_info info;
    void* self = nullptr;  // glibc's handle of that binary (its link map)
    if (!dladdr1(reinterpret_cast<void*>(&own_search_path), &info, &self, RTLD_DL_LINKMAP) || !self)
        return {};
    Dl_serinfo size;
    if (dlinfo(self, RTLD_DI_SERINFOSIZE, &size) != 0) return {};
    std::vector<std::max_align_t> storage(size.dls_size / sizeof(std::max_align_t) + 1);
    auto* paths = reinterpret_cast<Dl_serinfo*>(storage.data());
    *paths = size;
    if (dlinfo(self, RTLD_DI_SERINFOSIZE, paths) != 0 || dlinfo(self, RTLD_DI_SERINFO, paths) != 0)
        return {};
    std::vector<std::string> folders;
    for (unsigned i = 0; i < paths->dls_cnt; ++i) folders.push_back(paths->dls_serpath[i].dls_name);
    return folders;
}

struct LoadedReader {
    ReadImagePixels read = nullptr;
    std::string error;  // why there is none
};

// The first copy of the module on the search path, and its entry point.
LoadedReader load_image_reader() {
    LoadedReader loaded;
    const std::vector<std::string> folders = own_search_path();
    for (const std::string& folder : folders) {
        const std::string path = folder + "/" + RAYSET_IMAGE_READER_FILE;
        if (access(path.c_str(), F_OK) != 0) continue;
        void* module = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (module)
            loaded.read = reinterpret_cast<ReadImagePixels>(dlsym(module, kImageReaderEntry));
        if (!loaded.read) {
            const char* why = dlerror();
            loaded.error = why ? why : path + ": no entry point";
        }
        return loaded;
    }
    loaded.error = fmt::format(
        "{} is in none of {}", RAYSET_IMAGE_READER_FILE,
        folders.empty() ? "the folders searched" : fmt::format("{}", fmt::join(folders, ", ")));
    return loaded;
}

// The module's entry point, the module loaded on the first call; throws when it cannot be.
ReadImagePixels image_reader() {
    static const LoadedReader loaded = load_image_reader();
    if (!loaded.read)
        throw Error(fmt::format(
            "cannot read images: the image reader module did not load ({}); it is installed in "
            "lib/rayset beside the folder of the rayset programs (in the package folder for the "
            "Python module): reinstall rayset",
            loaded.error));
    return loaded.read;
}

}  // namespace

bool image_type_is_read(const std::string& type) {
    return type != "iff" && type != "pot" && type != "sys";
}

double ImageGamma::decode(double value) const {
    switch (kind) {
        case Kind::linear: return value;
        case Kind::power: return value <= 0 ? 0 : std::pow(value, power);
        case Kind::srgb: return srgb_to_linear(value);
    }
    return value;
}

double ImageGamma::encode(double linear) const {
    switch (kind) {
        case Kind::linear: return linear;
        case Kind::power: return linear <= 0 ? 0 : std::pow(linear, 1 / power);
        case Kind::srgb:
            return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1 / 2.4) - 0.055;
    }
    return linear;
}

std::shared_ptr<const ImagePixels> read_image_file(const std::string& path,
                                                   const std::string& type) {
    if (!image_type_is_read(type))
        throw Error(fmt::format("not supported: {} images ({}): convert it to PNG, TGA or EXR",
                                type, path));
    if (is_damaged_png(path))
        throw Error(
            fmt::format("cannot read the pixels of the image {}: its PNG data is damaged "
                        "or cut short",
                        path));
    auto pixels = std::make_shared<ImagePixels>();
    ImageReadOutcome outcome;
    image_reader()(path.c_str(), *pixels, outcome);
    switch (outcome.status) {
        case ImageReadOutcome::Status::read: break;
        case ImageReadOutcome::Status::cannot_open:
            throw Error(
                fmt::format("cannot read the image {}: {} (PNG, JPEG, GIF, TGA, BMP, TIFF, "
                            "PPM/PGM, HDR and EXR are read)",
                            path, outcome.message));
        case ImageReadOutcome::Status::no_pixels:
            throw Error(fmt::format("the image {} has no pixels of its own", path));
        case ImageReadOutcome::Status::cannot_read_pixels:
            throw Error(
                fmt::format("cannot read the pixels of the image {}: {}", path, outcome.message));
    }
    const std::string& format_name = outcome.format;
    pixels->palette = format_name == "gif" || (format_name == "png" && png_has_palette(path));
    if (pixels->palette && format_name == "png") read_palette_indices(path, *pixels);
    return pixels;
}

}  // namespace rayset::tracer
