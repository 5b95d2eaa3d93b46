// Image files for image_map, bump_map, image_pattern and height_field, read while parsing as
// POV-Ray reads them (through OpenImageIO): PNG, JPEG, GIF, TGA, BMP, TIFF, PPM/PGM, HDR, EXR.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace rayset::tracer {

// How a file's numbers encode light. POV-Ray 3.7 reads PNG as sRGB unless it carries a gAMA
// chunk (then that power), JPEG, GIF, TGA, BMP and TIFF as sRGB, PPM and PGM as linear (its
// renders of grey ramps in each format), HDR and EXR as the linear floats they are.
struct ImageGamma {
    enum class Kind { linear, power, srgb } kind = Kind::linear;
    double power = 1;  // power: linear = value^power
    double decode(double value) const;
    double encode(double linear) const;  // the inverse
};

struct ImagePixels {
    int width = 0, height = 0;
    // Per pixel, rows from the top of the image: red, green, blue as the file's numbers over
    // their maximum (no gamma applied; floats as they are) and alpha (1 where the file has
    // none).
    std::vector<float> values;
    bool has_alpha = false;
    bool grey = false;     // one channel (or grey and alpha)
    bool palette = false;  // the file's pixels are indices into a palette (PNG, GIF)
    // A PNG palette image's index of each pixel (rows from the top); empty otherwise.
    std::vector<uint8_t> indices;
    bool floating = false;  // HDR, EXR, float TIFF
    int bits = 8;           // per channel as stored
    ImageGamma gamma;       // what the file's format and header say
    const float* pixel(int column, int row) const {
        return &values[4 * (size_t(row) * size_t(width) + size_t(column))];
    }
};

// Whether files of POV-Ray's type keyword `type` are read (all but iff, pot and sys).
bool image_type_is_read(const std::string& type);

// Reads `path`; `type` is the POV-Ray type keyword written before it (png, jpeg, ...; empty:
// none). Throws rayset::Error naming the file and what is wrong with it: not readable as an
// image, a type POV-Ray defines that is not read here (iff, pot, sys), or no pixels.
std::shared_ptr<const ImagePixels> read_image_file(const std::string& path,
                                                   const std::string& type);

}  // namespace rayset::tracer
