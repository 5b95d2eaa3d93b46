// The image reader module (image_reader_module.h): image files through OpenImageIO.
#include <cmath>
#include <type_traits>
#include <vector>

#include <OpenImageIO/imageio.h>

#include "tracer/scene_language/image_reader_module.h"

namespace rayset::tracer {
namespace {

// OpenImageIO's messages, one line each, as one line.
std::string one_line(std::string text) {
    while (!text.empty() && text.back() == '\n') text.pop_back();
    for (size_t at = text.find('\n'); at != std::string::npos; at = text.find('\n', at))
        text.replace(at, 1, "; ");
    return text;
}

// POV-Ray 3.7 decodes a PNG by its gAMA chunk when it has one (as the power that decodes it)
// and as sRGB otherwise, the other 8-bit formats as sRGB, PPM/PGM and floats as linear.
ImageGamma gamma_of(const OIIO::ImageSpec& spec, const std::string& format, bool floating) {
    const float png_gamma =
        format == "png" && spec.get_string_attribute("oiio:ColorSpace") != "sRGB"
            ? spec.get_float_attribute("oiio:Gamma", 0)
            : 0;
    if (floating || format == "pnm" || std::fabs(png_gamma - 1) < 1e-3)
        return {ImageGamma::Kind::linear, 1};
    if (png_gamma > 0) return {ImageGamma::Kind::power, png_gamma};
    return {ImageGamma::Kind::srgb, 1};
}

// The file's channels as red, green, blue and alpha per pixel.
void expand_to_rgba(const std::vector<float>& file, int channels, ImagePixels& pixels) {
    const size_t count = size_t(pixels.width) * size_t(pixels.height);
    pixels.values.resize(count * 4);
    for (size_t i = 0; i < count; ++i) {
        const float* in = &file[i * size_t(channels)];
        float* out = &pixels.values[i * 4];
        if (pixels.grey) {
            out[0] = out[1] = out[2] = in[0];
        } else {
            out[0] = in[0], out[1] = in[1], out[2] = in[2];
        }
        out[3] = pixels.has_alpha ? in[channels - 1] : 1.0f;
    }
}

}  // namespace
}  // namespace rayset::tracer

extern "C" __attribute__((visibility("default"))) void rayset_read_image_pixels(
    const char* path, rayset::tracer::ImagePixels& pixels,
    rayset::tracer::ImageReadOutcome& outcome) {
    using rayset::tracer::ImageReadOutcome;
    using Status = ImageReadOutcome::Status;
    auto input = OIIO::ImageInput::open(path);
    if (!input) {
        outcome = {Status::cannot_open, rayset::tracer::one_line(OIIO::geterror()), ""};
        return;
    }
    const OIIO::ImageSpec& spec = input->spec();
    const int channels = spec.nchannels;
    outcome.format = input->format_name();
    if (spec.width <= 0 || spec.height <= 0 || channels <= 0 || spec.depth > 1) {
        outcome.status = Status::no_pixels;
        return;
    }
    pixels.width = spec.width;
    pixels.height = spec.height;
    pixels.has_alpha = spec.alpha_channel >= 0 || channels == 2 || channels == 4;
    pixels.grey = channels <= 2;
    pixels.floating = spec.format.is_floating_point();
    pixels.bits = int(spec.format.size()) * 8;
    pixels.gamma = rayset::tracer::gamma_of(spec, outcome.format, pixels.floating);
    std::vector<float> file(size_t(spec.width) * size_t(spec.height) * size_t(channels));
    if (!input->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, file.data())) {
        outcome.status = Status::cannot_read_pixels;
        outcome.message = rayset::tracer::one_line(input->geterror());
        return;
    }
    rayset::tracer::expand_to_rgba(file, channels, pixels);
    outcome.status = Status::read;
}
static_assert(std::is_same_v<decltype(&rayset_read_image_pixels), rayset::tracer::ReadImagePixels>,
              "the entry point has the type image_file.cpp calls it by");
