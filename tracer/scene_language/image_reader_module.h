// The contract between image_file.cpp and the image reader module (image_reader/). Debian's
// OpenImageIO links about 260 shared libraries (OpenCV, FFmpeg, GDAL, ...); linked into every
// program that can parse a scene, loading them took 0.17 s at each start. The module holds the
// one use of OpenImageIO and is loaded (dlopen) on the first image a scene reads, found through
// the run path of the program or the Python module: lib/rayset beside the program's folder
// (build tree and installed alike), the package folder for the Python module.
#pragma once

#include <string>

#include "tracer/scene_language/image_file.h"

namespace rayset::tracer {

struct ImageReadOutcome {
    enum class Status { read, cannot_open, no_pixels, cannot_read_pixels };
    Status status = Status::read;
    std::string message;  // the library's words, one line, when not read
    std::string format;   // the format the file was read as (png, gif, pnm, openexr, ...)
};

// Fills everything of `pixels` but the palette (its flag and indices): size, channels, values,
// bits, and the gamma the format and its header give.
using ReadImagePixels = void (*)(const char* path, ImagePixels& pixels, ImageReadOutcome& outcome);

// The entry point's name; the module's file name comes from the build (RAYSET_IMAGE_READER_FILE,
// given to image_file.cpp).
inline constexpr const char* kImageReaderEntry = "rayset_read_image_pixels";

}  // namespace rayset::tracer
