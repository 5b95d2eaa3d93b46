#include "converters/photometry/emit.h"

#include "converters/rays/io.h"
#include "core/error.h"
#include "core/geometry.h"

#include <algorithm>
#include <cmath>

namespace rayset {

namespace {

bool radiometric(const Photometry& p) { return p.keywords.count("_RADIOMETRIC") != 0; }

// The emitting area as an ellipse (semi-axes) or a rectangle (full sides), in mm; zero = point.
struct Shape {
    bool ellipse = false;
    double x = 0, y = 0;
};

Shape shape_of(const Photometry& p, const EmitOptions& o) {
    auto check = [&](const char* what, double mm) {
        if (!(mm > 0 && std::isfinite(mm)))
            throw Error(o.name + ": the emitter " + what +
                        " must be a positive number of mm, not " + format_double(mm));
    };
    switch (o.shape) {
        case EmitterShape::point: return {};
        case EmitterShape::disk:
            check("radius", o.radius_mm);
            return {true, o.radius_mm, o.radius_mm};
        case EmitterShape::rectangle:
            check("size x", o.size_x_mm);
            check("size y", o.size_y_mm);
            return {false, o.size_x_mm, o.size_y_mm};
        case EmitterShape::opening: {
            const double length = std::abs(p.length_m) * 1000, width = std::abs(p.width_m) * 1000;
            if (!std::isfinite(length) || !std::isfinite(width))
                throw Error(o.name + ": the luminous opening is not finite");
            if (length == 0 || width == 0) return {};  // a point (or a line, which carries no area)
            return p.round ? Shape{true, length / 2, width / 2} : Shape{false, length, width};
        }
    }
    return {};
}

std::string shape_text(const Shape& s) {
    if (s.x == 0) return "point";
    if (s.ellipse)
        return "ellipse " + format_double(2 * s.x) + " x " + format_double(2 * s.y) + " mm";
    return "rectangle " + format_double(s.x) + " x " + format_double(s.y) + " mm";
}

Vec3f origin(const Shape& s, Pcg32& rng) {
    if (s.x == 0) return {};
    if (!s.ellipse)
        return {float((rng.uniform() - 0.5) * s.x), float((rng.uniform() - 0.5) * s.y), 0};
    double u, v;
    do {
        u = 2 * rng.uniform() - 1;
        v = 2 * rng.uniform() - 1;
    } while (u * u + v * v >= 1);
    return {float(u * s.x), float(v * s.y), 0};
}

}  // namespace

RayHeader emit_header(const Photometry& photometry, uint64_t ray_count, uint64_t seed,
                      const EmitOptions& options) {
    const IntensityDistribution distribution(photometry, options.name);
    RayHeader h;
    h.unit = LengthUnit::mm;
    h.ray_count = ray_count;
    h.creation_method = 0;
    if (radiometric(photometry)) {
        h.has_radiant = true;
        h.stated_radiant = distribution.total_flux();
    } else {
        h.has_luminous = true;
        h.stated_luminous = distribution.total_flux();
    }
    auto keyword = [&](const char* key) {
        auto it = photometry.keywords.find(key);
        return it == photometry.keywords.end() ? std::string() : it->second;
    };
    h.text[0] = keyword("LUMINAIRE").empty() ? options.name : keyword("LUMINAIRE");
    h.text[1] = keyword("MANUFAC");
    h.text[3] = "rayset emit";
    h.text[4] = "rayset converters/emit";
    h.text[7] = "rays from the far field of " + options.name + ": " +
                shape_text(shape_of(photometry, options)) + ", gamma 0 along " +
                (options.axis == PolarAxis::plus_z ? "+z" : "-z") +
                ", rays=" + std::to_string(ray_count) + " seed=" + std::to_string(seed);
    h.description = h.text[7];
    return h;
}

void emit_rays(const Photometry& photometry, uint64_t ray_count, uint64_t seed, RayEncoder& out,
               const EmitOptions& options) {
    if (ray_count == 0) throw Error(options.name + ": the ray count must be at least 1");
    const IntensityDistribution distribution(photometry, options.name);
    const Shape shape = shape_of(photometry, options);
    const bool radiant = radiometric(photometry);
    const float flux = float(distribution.total_flux() / double(ray_count));
    const double polar = options.axis == PolarAxis::plus_z ? 1 : -1;
    Pcg32 rng(seed);
    RayChunk chunk;
    const size_t chunk_size = std::max<size_t>(options.chunk_size, 1);
    for (uint64_t done = 0; done < ray_count;) {
        const size_t n = size_t(std::min<uint64_t>(chunk_size, ray_count - done));
        chunk.clear();
        chunk.first_index = done;
        for (size_t i = 0; i < n; ++i) {
            double c, gamma;
            distribution.sample(rng, c, gamma);
            Ray ray;
            ray.origin = origin(shape, rng);
            const double sg = std::sin(gamma * kRadiansPerDegree);
            ray.direction = {float(sg * std::cos(c * kRadiansPerDegree)),
                             float(sg * std::sin(c * kRadiansPerDegree)),
                             float(polar * std::cos(gamma * kRadiansPerDegree))};
            (radiant ? ray.radiant : ray.luminous) = flux;
            chunk.rays.push_back(ray);
        }
        out.write(chunk);
        done += n;
        if (options.progress) options.progress(double(done) / double(ray_count));
    }
    out.finish();
}

}  // namespace rayset
