// Rays from far-field photometry: directions drawn from the interpolated type C intensity
// (IntensityDistribution), origins spread uniformly over an emitter shape, equal fluxes that
// sum to the distribution's flux. Types A and B are refused with an Error.
#pragma once

#include "converters/photometry/emit_distribution.h"
#include "converters/photometry/farfield.h"
#include "converters/photometry/photometry.h"
#include "converters/rays/ray_stream.h"

#include <cstdint>
#include <functional>
#include <string>

namespace rayset {

enum class EmitterShape {
    point,      // every ray from the origin
    disk,       // radius_mm, in the plane z = 0
    rectangle,  // size_x_mm by size_y_mm, centred, in z = 0
    opening,    // the photometry's luminous opening: length along C0-C180 (x), width along
                // C90-C270 (y), an ellipse if round; its height is ignored; a point if zero
};

struct EmitOptions {
    // The ray-file axis gamma 0 points along; C0 is +x and C90 +y either way, as in far_field(),
    // so far_field(emit(p)) with the same axis reproduces p.
    PolarAxis axis = PolarAxis::plus_z;
    EmitterShape shape = EmitterShape::point;
    double radius_mm = 0;
    double size_x_mm = 0, size_y_mm = 0;
    std::string name = "photometry";  // the file, for messages and the header's text
    size_t chunk_size = 1 << 16;
    std::function<void(double)> progress;  // fraction done
};

// Header of the rays emit_rays() writes: mm, luminous flux (radiant flux when the photometry is
// a radiometric far field, keyword _RADIOMETRIC), no spectrum, stated total = the exact flux of
// the interpolated distribution, text naming the source, the shape, the ray count and the seed.
RayHeader emit_header(const Photometry& photometry, uint64_t ray_count, uint64_t seed,
                      const EmitOptions& options = {});

// Writes ray_count rays of equal flux total/ray_count drawn with Pcg32(seed) into `out` (created
// with emit_header() of the same arguments), then calls out.finish().
void emit_rays(const Photometry& photometry, uint64_t ray_count, uint64_t seed, RayEncoder& out,
               const EmitOptions& options = {});

}  // namespace rayset
