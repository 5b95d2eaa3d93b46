// OpenEXR and PNG writing, and the preview tone mapping.
#include "tracer/film/image_writers.h"

#include <algorithm>
#include <cmath>
#include <csetjmp>
#include <cstdio>

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>
#include <ImfStringAttribute.h>
#include <fmt/format.h>
#include <png.h>

#include "core/error.h"

namespace rayset::tracer {

void write_exr(const std::string& path, int width, int height,
               const std::vector<ExrChannel>& channels,
               const std::vector<std::pair<std::string, std::string>>& attributes) {
    try {
        Imf::Header header(width, height);
        for (const auto& [key, value] : attributes) header.insert(key, Imf::StringAttribute(value));
        Imf::FrameBuffer frame;
        for (const ExrChannel& c : channels) {
            header.channels().insert(c.name, Imf::Channel(Imf::FLOAT));
            frame.insert(c.name, Imf::Slice(Imf::FLOAT, (char*)c.values.data(), sizeof(float),
                                            sizeof(float) * size_t(width)));
        }
        Imf::OutputFile file(path.c_str(), header);
        file.setFrameBuffer(frame);
        file.writePixels(height);
    } catch (const std::exception& e) {
        throw Error(fmt::format("{}: cannot write OpenEXR: {}", path, e.what()));
    }
}

namespace {

// libpng reports errors by longjmp; this keeps the C++ objects outside that frame.
bool write_png_rows(std::FILE* file, int width, int height, const uint8_t* rgb) {
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    if (!png) return false;
    png_infop info = png_create_info_struct(png);
    if (!info || setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        return false;
    }
    png_init_io(png, file);
    png_set_IHDR(png, info, png_uint_32(width), png_uint_32(height), 8, PNG_COLOR_TYPE_RGB,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
    png_write_info(png, info);
    for (int y = 0; y < height; ++y)
        png_write_row(png, const_cast<uint8_t*>(rgb + size_t(y) * width * 3));
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    return true;
}

double srgb_transfer(double linear) {
    return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1 / 2.4) - 0.055;
}

}  // namespace

void write_png(const std::string& path, int width, int height, const std::vector<uint8_t>& rgb) {
    std::FILE* file = std::fopen(path.c_str(), "wb");
    if (!file) throw Error(fmt::format("{}: cannot create the PNG file", path));
    const bool ok = write_png_rows(file, width, height, rgb.data());
    if (std::fclose(file) != 0 || !ok)
        throw Error(fmt::format("{}: cannot write the PNG file", path));
}

std::vector<uint8_t> tone_map_srgb(const Film& film, double exposure) {
    const int w = film.nx(), h = film.ny();
    if (exposure <= 0) {
        // Over the lit pixels only: an image of a small source on black (the direct-visibility
        // layer) is exposed for the source, not for the black around it. By the largest
        // channel, not luminance: a saturated blue has little luminance but a large blue value.
        std::vector<double> brightest;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                if (const double v = max_component(film.mean(x, y)); v > 0) brightest.push_back(v);
        exposure = 1;
        if (!brightest.empty()) {
            const size_t k =
                std::min(brightest.size() - 1, size_t(0.99 * double(brightest.size())));
            std::nth_element(brightest.begin(), brightest.begin() + k, brightest.end());
            exposure = 1 / brightest[k];
        }
    }
    std::vector<uint8_t> rgb;
    rgb.reserve(size_t(w) * h * 3);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            Rgb c = exposure * film.mean(x, y);
            // Too bright: scaled down as a whole, so the hue stays (a clipped blue chip would
            // otherwise turn magenta, a green one cyan).
            if (const double m = max_component(c); m > 1) c = (1 / m) * c;
            for (double v : {c.red, c.green, c.blue})
                rgb.push_back(uint8_t(std::lround(255 * srgb_transfer(std::clamp(v, 0.0, 1.0)))));
        }
    return rgb;
}

}  // namespace rayset::tracer
