// Evaluation of patterns and pigments at a point (pattern and pigment functions, and the
// renderer's textures): exact for solid colours, image maps (image_mapping.h) and the patterns
// that need no noise or surface: boxed, brick, checker, cubic, cylindrical, function, gradient,
// hexagon, julia and mandel (exponent 2), leopard, marble, wood, object (where the object can
// answer), onion, pigment_pattern (of such pigments), planar, radial, spherical, spiral1, square
// and triangular, through transforms, frequency, phase, waveforms and colour, pigment and list
// maps. The noise
// patterns (agate, bozo, bumps, crackle, dents, granite, spotted, wrinkles) and turbulence agree
// with POV-Ray's in distribution and spectrum, not point for point (noise.h). Everything else
// returns false.
//
// Every rule below was read back from POV-Ray 3.7 itself through `function { pattern { ... } }`
// and `function { pigment { ... } }` at random points (to 1e-6), since the manual leaves the
// details out: the wrap of values by fmod(v, 1.00001), the ranges of gradient and radial, the
// layout of brick, hexagon, square and triangular, and the order of map lookups.
#include <algorithm>
#include <cmath>

#include "core/geometry.h"
#include "tracer/scene_language/appearance_grammar.h"
#include "tracer/scene_language/functions.h"
#include "tracer/scene_language/image_mapping.h"
#include "tracer/scene_language/noise.h"
#include "tracer/scene_language/object_tree.h"

namespace rayset::tracer {
namespace {

double fraction(double v) { return v - std::floor(v); }

Vec3 times(Vec3 a, Vec3 b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }

Vec3 turbulence_displacement(const Turbulence& turbulence, Vec3 point) {
    return times(turbulence.amount,
                 vector_turbulence(point, turbulence.octaves, turbulence.omega, turbulence.lambda));
}

// Wood takes the classic turbulence in its own way (read back from POV-Ray's spectra: a plain
// displacement decorrelates its rings five times too slowly).
bool own_turbulence(PatternKind kind) { return kind == PatternKind::wood; }

// z -> z^2 + c from z = `start` until |z| > 2 (the first step counted as 0), over
// `iterations` steps: the step it escapes at over `iterations`, or 1 where it never does. The
// plain Mandelbrot and Julia sets (exponent 2, POV-Ray's default exterior and interior).
bool escape_time(const FractalParameters& f, double start_x, double start_y, double c_x, double c_y,
                 double& value) {
    if (f.magnet != 0 || f.exponent != 2 || f.exterior_type != 1 || f.exterior_factor != 1 ||
        f.interior_type != 0 || f.interior_factor != 1 || f.iterations <= 0)
        return false;
    double x = start_x, y = start_y;
    for (int i = 0; i < f.iterations; ++i) {
        const double next_x = x * x - y * y + c_x;
        y = 2 * x * y + c_y, x = next_x;
        if (x * x + y * y > 4) {
            value = double(i) / f.iterations;
            return true;
        }
    }
    value = 1;
    return true;
}

// Rings around z, each axis pushed by a sine of the turbulent coordinate: x + sin(2 pi (x +
// T.x) a.x), the same for y, with T the vector turbulence and a the turbulence amount.
double wood(const Pattern& pattern, Vec3 p) {
    const Turbulence& turbulence = pattern.turbulence;
    if (is_zero(turbulence.amount)) return std::sqrt(p.x * p.x + p.y * p.y);
    const Vec3 t = vector_turbulence(p, turbulence.octaves, turbulence.omega, turbulence.lambda);
    const double x = p.x + std::sin(2 * kPi * (p.x + t.x) * turbulence.amount.x);
    const double y = p.y + std::sin(2 * kPi * (p.y + t.y) * turbulence.amount.y);
    return std::sqrt(x * x + y * y);
}

// Bands along z bent by seven octaves of noise scaled by agate_turb, raised to 0.77 (the
// power and the two rates read back from POV-Ray's mean, spread and spectrum).
double agate(const Pattern& pattern, Vec3 p) {
    const double bend =
        2.6 * pattern.agate_turbulence * scalar_turbulence(p, 7, 0.5, 2, pattern.noise_generator);
    return std::pow(0.5 * (1 + std::sin(2 * kPi * (bend + 1.1 * p.z))), 0.77);
}

// 1/f noise over ten octaves from the base rate, centred on 0.5.
double wrinkles(const Pattern& pattern, Vec3 p) {
    double sum = 0.5, rate = 1;
    for (int octave = 0; octave < 10; ++octave, rate *= 2)
        sum += (solid_noise(rate * p, pattern.noise_generator) - 0.5) / rate;
    return std::clamp(sum, 0.0, 1.0);
}

// Crackle: the weighted distances to the nearest three cell points (form), or with `solid`
// the noise at the nearest point (read back from POV-Ray's statistics), within [0, 1].
double crackle(const Pattern& pattern, Vec3 p) {
    const CrackleParameters& c = pattern.crackle;
    const CellDistances cells = cell_distances(p, c.metric, c.offset);
    if (c.solid) return solid_noise(cells.nearest_point, pattern.noise_generator);
    const double v =
        c.form.x * cells.nearest[0] + c.form.y * cells.nearest[1] + c.form.z * cells.nearest[2];
    return std::clamp(v, 0.0, 1.0);
}

// The absolute 1/f noise over six octaves from four times the base rate.
double granite(const Pattern& pattern, Vec3 p) {
    double sum = 0, rate = 4;
    for (int octave = 0; octave < 6; ++octave, rate *= 2)
        sum += std::fabs(1 - 2 * solid_noise(rate * p, pattern.noise_generator)) * 4 / rate;
    return sum;
}

// gradient and function: values above 1 keep their fraction, the rest stay for the wrap.
double above_one_wrapped(double v) { return v > 1 ? std::fmod(v, 1.0) : v; }

// radial: the angle from +x toward -z in turns, in (0.25, 1.25]; 0.25 on the y axis.
double radial(Vec3 p) {
    if (p.x == 0 && p.z == 0) return 0.25;
    const double turns = std::atan2(-p.z, p.x) / (2 * kPi);
    return 1.25 - fraction(1.25 - turns);
}

// floor(v) mod n in [0, n), safe for any v (an infinite or undefined one gives 0).
int cell_mod(double v, int n) {
    const double cell = std::floor(v);
    if (!std::isfinite(cell)) return 0;
    double r = std::fmod(cell, n);
    if (r < 0) r += n;
    return static_cast<int>(r);
}

int brick(Vec3 p, Vec3 size, double mortar) {
    // Even rows of bricks (along y) are offset by half a brick along z, odd rows along x;
    // mortar fills the last `mortar` of each brick along every axis.
    if (cell_mod(p.y / size.y, 2) == 0)
        p.z += size.z / 2;
    else
        p.x += size.x / 2;
    const bool in_mortar = fraction(p.x / size.x) >= 1 - mortar / size.x ||
                           fraction(p.y / size.y) >= 1 - mortar / size.y ||
                           fraction(p.z / size.z) >= 1 - mortar / size.z;
    return in_mortar ? 0 : 1;
}

// Hexagons of side 1 in the x-z plane, one centred at the origin (0), its neighbour toward +z
// (1) and the ones beside (2): axial coordinates rounded to the nearest hexagon.
int hexagon(Vec3 p) {
    const double q = 2.0 / 3.0 * p.x, r = -p.x / 3.0 + std::sqrt(3.0) / 3.0 * p.z, s = -q - r;
    double rq = std::round(q), rr = std::round(r), rs = std::round(s);
    const double dq = std::fabs(rq - q), dr = std::fabs(rr - r), ds = std::fabs(rs - s);
    if (dq > dr && dq > ds)
        rq = -rr - rs;
    else if (!(dr > ds))
        rr = -rq - rs;
    return cell_mod(2 * rq + rr, 3);
}

int square(Vec3 p) {
    static const int kIndex[2][2] = {{0, 1}, {3, 2}};  // [x cell mod 2][z cell mod 2]
    return kIndex[cell_mod(p.x, 2)][cell_mod(p.z, 2)];
}

// Equilateral triangles of side 1 in the x-z plane in rows of height sqrt(3)/2 from z = 0.
int triangular(Vec3 p) {
    static const int kIndex[3][2] = {{0, 3}, {4, 5}, {2, 1}};  // [(i + 2 row) mod 3][down]
    const double rows = p.z / (std::sqrt(3.0) / 2);
    const double row = std::floor(rows);
    const double skewed = p.x - 0.5 * rows;
    const double column = std::floor(skewed);
    const bool down = (skewed - column) + (rows - row) >= 1;
    return kIndex[(cell_mod(column, 3) + 2 * cell_mod(row, 3)) % 3][down ? 1 : 0];
}

int cubic(Vec3 p) {
    const double ax = std::fabs(p.x), ay = std::fabs(p.y), az = std::fabs(p.z);
    if (ax >= ay && ax >= az) return p.x > 0 ? 0 : 3;
    if (ay >= az) return p.y > 0 ? 1 : 4;
    return p.z > 0 ? 2 : 5;
}

// The value of a pattern made of another thing: an object's inside, a pigment's grey, a
// function; false for any other pattern, or where the thing is not known.
bool nested_value(const Pattern& pattern, Vec3 p, double& value) {
    switch (pattern.kind) {
        case PatternKind::object: {
            bool inside = false;
            if (!pattern.object || !object_inside(*pattern.object, p, inside)) return false;
            value = inside ? 1 : 0;
            return true;
        }
        case PatternKind::pigment_pattern: {
            // The pigment's grey (POV-Ray's weights; filter and transmit play no part).
            Colour c;
            if (!pattern.pigment || !evaluate_pigment(*pattern.pigment, p, c)) return false;
            value = 0.297 * c.red + 0.589 * c.green + 0.114 * c.blue;
            return true;
        }
        case PatternKind::function: {
            if (!pattern.function || pattern.function->result_terms() != 1) return false;
            const double arguments[3] = {p.x, p.y, p.z};
            try {
                value = above_one_wrapped(pattern.function->evaluate(arguments).v[0]);
            } catch (const FunctionNotSupported&) {
                return false;
            }
            return true;
        }
        default: return false;
    }
}

// The pattern's own value before frequency, phase and waveform; false when not exact here.
bool raw_value(const Pattern& pattern, Vec3 p, double& value) {
    const double length = std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
    switch (pattern.kind) {
        case PatternKind::boxed:
            value = 1 - std::min(1.0, std::max({std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)}));
            return true;
        case PatternKind::spherical: value = 1 - std::min(1.0, length); return true;
        case PatternKind::cylindrical:
            value = 1 - std::min(1.0, std::sqrt(p.x * p.x + p.z * p.z));
            return true;
        case PatternKind::planar: value = 1 - std::min(1.0, std::fabs(p.y)); return true;
        case PatternKind::onion: value = std::fmod(length, 1.0); return true;
        case PatternKind::leopard: {
            const double s = (std::sin(p.x) + std::sin(p.y) + std::sin(p.z)) / 3;
            value = s * s;
            return true;
        }
        case PatternKind::marble: value = p.x; return true;
        case PatternKind::wood: value = wood(pattern, p); return true;
        case PatternKind::bozo:
        case PatternKind::spotted:
        case PatternKind::bumps: value = solid_noise(p, pattern.noise_generator); return true;
        case PatternKind::granite: value = granite(pattern, p); return true;
        case PatternKind::wrinkles: value = wrinkles(pattern, p); return true;
        case PatternKind::dents:
            value = std::pow(solid_noise(p, pattern.noise_generator), 3);
            return true;
        case PatternKind::agate: value = agate(pattern, p); return true;
        case PatternKind::crackle: value = crackle(pattern, p); return true;
        case PatternKind::radial: value = radial(p); return true;
        case PatternKind::spiral1:
            // Arms around z that climb one unit along z and out along the radius per turn; the
            // turn's fraction measured from -y, in [0, 1).
            value = std::sqrt(p.x * p.x + p.y * p.y) + p.z +
                    pattern.spiral_arms * fraction(std::atan2(p.y, p.x) / (2 * kPi) + 0.25);
            return true;
        case PatternKind::mandel: return escape_time(pattern.fractal, p.x, p.y, p.x, p.y, value);
        case PatternKind::julia:
            return escape_time(pattern.fractal, p.x, p.y, pattern.fractal.julia_real,
                               pattern.fractal.julia_imaginary, value);
        case PatternKind::gradient: {
            const Vec3 g = pattern.gradient;
            const double norm = std::sqrt(g.x * g.x + g.y * g.y + g.z * g.z);
            if (norm == 0) return false;
            value = above_one_wrapped((p.x * g.x + p.y * g.y + p.z * g.z) / norm);
            return true;
        }
        case PatternKind::checker:
            value = cell_mod(std::floor(p.x) + std::floor(p.y) + std::floor(p.z), 2);
            return true;
        case PatternKind::brick: value = brick(p, pattern.brick_size, pattern.mortar); return true;
        case PatternKind::hexagon: value = hexagon(p); return true;
        case PatternKind::square: value = square(p); return true;
        case PatternKind::triangular: value = triangular(p); return true;
        case PatternKind::cubic: value = cubic(p); return true;
        default: return nested_value(pattern, p, value);
    }
}

double shaped(Waveform waveform, double exponent, double v) {
    switch (waveform) {
        case Waveform::ramp: return v;
        case Waveform::triangle: {
            const double f = fraction(v);
            return f < 0.5 ? 2 * f : 2 * (1 - f);
        }
        case Waveform::sine: return (std::sin(2 * kPi * v) + 1) / 2;
        case Waveform::scallop: return std::fabs(std::sin(kPi * v));
        case Waveform::cubic: return v * v * (3 - 2 * v);
        case Waveform::poly: return std::pow(v, exponent);
    }
    return v;
}

Colour blend(const Colour& a, const Colour& b, double t) {
    return {a.red + t * (b.red - a.red), a.green + t * (b.green - a.green),
            a.blue + t * (b.blue - a.blue), a.filter + t * (b.filter - a.filter),
            a.transmit + t * (b.transmit - a.transmit)};
}

template <class Item, class ItemAt>
bool look_up(const BlendMap& map, double v, Item& out, ItemAt&& item_at) {
    MapBlend where;
    if (!look_up_map(map, v, where)) return false;
    if (where.weight == 0) return item_at(map.entries[where.low], out);
    Item low, high;
    if (!item_at(map.entries[where.low], low) || !item_at(map.entries[where.high], high))
        return false;
    out = blend(low, high, where.weight);
    return true;
}

bool colour_of_entry(const BlendMapEntry& entry, BlendMapKind kind, Vec3 point, Colour& colour) {
    if (kind == BlendMapKind::colour) {
        colour = entry.colour;
        return true;
    }
    return entry.pigment && evaluate_pigment(*entry.pigment, point, colour);
}

// average: the entries' colours weighted by their values.
bool average_colour(const BlendMap& map, Vec3 point, Colour& colour) {
    double sum[5] = {0, 0, 0, 0, 0};
    double total = 0;
    for (const BlendMapEntry& entry : map.entries) {
        Colour c;
        if (!colour_of_entry(entry, map.kind, point, c)) return false;
        const double terms[5] = {c.red, c.green, c.blue, c.filter, c.transmit};
        for (int i = 0; i < 5; ++i) sum[i] += entry.value * terms[i];
        total += entry.value;
    }
    if (total == 0) return false;
    colour = {sum[0] / total, sum[1] / total, sum[2] / total, sum[3] / total, sum[4] / total};
    return true;
}

}  // namespace

// Every warp undone from the last written to the first, then the classic turbulence.
bool pattern_space_point(const Pattern& pattern, Vec3& point) {
    if (pattern.uv_mapping) return false;  // needs a surface's u, v
    for (auto warp = pattern.warps.rbegin(); warp != pattern.warps.rend(); ++warp) {
        if (warp->kind == Warp::Kind::transform)
            point = warp->transform.inverse().point(point);
        else if (warp->kind == Warp::Kind::turbulence)
            point = point + turbulence_displacement(warp->turbulence, point);
        else
            return false;
    }
    if (!is_zero(pattern.turbulence.amount) && !own_turbulence(pattern.kind))
        point = point + turbulence_displacement(pattern.turbulence, point);
    return true;
}

Matrix4 pattern_to_world(const Pattern& pattern) {
    Matrix4 m;
    for (const Warp& warp : pattern.warps)
        if (warp.kind == Warp::Kind::transform) m = warp.transform * m;
    return m;
}

bool evaluate_pattern(const Pattern& pattern, Vec3 point, double& value) {
    if (!pattern_space_point(pattern, point) || !raw_value(pattern, point, value)) return false;
    // Frequency and phase: v' = fmod(v f + phase, 1.00001), negatives lifted by 1. POV-Ray
    // skips them for frequency 0, and for block patterns unless frequency is written.
    const bool block = list_size(pattern.kind) > 0;
    if (pattern.frequency != 0 && (!block || pattern.frequency_written)) {
        value = std::fmod(value * pattern.frequency + pattern.phase, 1.00001);
        if (value < 0) value += 1;
    }
    value = shaped(pattern.waveform, pattern.poly_exponent, value);
    return true;
}

bool look_up_map(const BlendMap& map, double v, MapBlend& blend) {
    const auto& e = map.entries;
    if (e.empty()) return false;
    blend = {};
    if (v >= e.back().value) {
        blend.low = blend.high = e.size() - 1;
        return true;
    }
    if (v <= e.front().value) return true;
    size_t i = 1;
    while (i < e.size() && !(v < e[i].value)) ++i;
    blend.low = i - 1;
    blend.high = i;
    const double span = e[i].value - e[i - 1].value;
    blend.weight = span > 0 ? (v - e[i - 1].value) / span : 0;
    return true;
}

constexpr Vec3 kProbe{0.31, -0.72, 1.13};

bool pattern_is_evaluable(const Pattern& pattern) {
    double value;
    return evaluate_pattern(pattern, kProbe, value);
}

bool pigment_is_evaluable(const Pigment& pigment) {
    Colour colour;
    return evaluate_pigment(pigment, kProbe, colour);
}

bool evaluate_pigment(const Pigment& pigment, Vec3 point, Colour& colour) {
    if (pigment.pattern->kind == PatternKind::plain) {
        colour = pigment.colour;
        return true;
    }
    if (pigment.pattern->kind == PatternKind::image_map) {
        const Pattern& pattern = *pigment.pattern;
        return pattern.image && pattern_space_point(pattern, point) &&
               image_map_colour(*pattern.image, point, colour);
    }
    const BlendMap& map = pigment.map ? *pigment.map : builtin_colour_map(pigment.pattern->kind);
    if (map.kind != BlendMapKind::colour && map.kind != BlendMapKind::pigment) return false;
    if (pigment.pattern->kind == PatternKind::average) return average_colour(map, point, colour);
    double value = 0;
    if (!evaluate_pattern(*pigment.pattern, point, value)) return false;
    return look_up(map, value, colour, [&](const BlendMapEntry& entry, Colour& c) {
        return colour_of_entry(entry, map.kind, point, c);
    });
}

}  // namespace rayset::tracer
