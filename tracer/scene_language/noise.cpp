#include "tracer/scene_language/noise.h"

#include <algorithm>
#include <cstdint>

namespace rayset::tracer {
namespace {

// MurmurHash3's finaliser: every input bit moves every output bit.
uint32_t mix(uint32_t h) {
    h ^= h >> 16;
    h *= 0x85EBCA6Bu;
    h ^= h >> 13;
    h *= 0xC2B2AE35u;
    h ^= h >> 16;
    return h;
}

uint32_t lattice_hash(int64_t x, int64_t y, int64_t z, uint32_t channel) {
    return mix(static_cast<uint32_t>(x) ^
               mix(static_cast<uint32_t>(y) ^ mix(static_cast<uint32_t>(z) ^ mix(channel))));
}

// The twelve edge directions of a cube (Perlin 2002): gradients without a preferred axis.
constexpr double kGradients[12][3] = {{1, 1, 0}, {-1, 1, 0}, {1, -1, 0}, {-1, -1, 0},
                                      {1, 0, 1}, {-1, 0, 1}, {1, 0, -1}, {-1, 0, -1},
                                      {0, 1, 1}, {0, -1, 1}, {0, 1, -1}, {0, -1, -1}};

// The unit cube of the lattice a point lies in, and the point's place in it; false beyond
// 10^15 (or not finite), where a double's cell is no longer a whole number we can hash.
struct LatticeCell {
    int64_t x, y, z;
    double f[3];
};
bool lattice_cell(Vec3 p, LatticeCell& cell) {
    constexpr double kLargest = 1e15;
    if (!(std::fabs(p.x) < kLargest && std::fabs(p.y) < kLargest && std::fabs(p.z) < kLargest))
        return false;
    const double cx = std::floor(p.x), cy = std::floor(p.y), cz = std::floor(p.z);
    cell = {static_cast<int64_t>(cx),
            static_cast<int64_t>(cy),
            static_cast<int64_t>(cz),
            {p.x - cx, p.y - cy, p.z - cz}};
    return true;
}

// Gradient noise plus `value_weight` times a lattice value uniform in [-1, 1], blended by
// 3t^2 - 2t^3; zero mean.
double lattice_noise(Vec3 p, double value_weight, uint32_t channel) {
    LatticeCell cell;
    if (!lattice_cell(p, cell)) return 0;
    const double* f = cell.f;
    double blend[3];
    for (int axis = 0; axis < 3; ++axis) blend[axis] = f[axis] * f[axis] * (3 - 2 * f[axis]);
    const int64_t ix = cell.x, iy = cell.y, iz = cell.z;
    double sum = 0;
    for (int corner = 0; corner < 8; ++corner) {
        const int d[3] = {corner & 1, (corner >> 1) & 1, (corner >> 2) & 1};
        const uint32_t h = lattice_hash(ix + d[0], iy + d[1], iz + d[2], channel);
        const double* g = kGradients[h % 12];
        const double value = (h >> 8 & 0xFFFF) / 32767.5 - 1;
        double weight = 1, gradient = 0;
        for (int axis = 0; axis < 3; ++axis) {
            weight *= d[axis] ? blend[axis] : 1 - blend[axis];
            gradient += g[axis] * (f[axis] - d[axis]);
        }
        sum += weight * (gradient + value_weight * value);
    }
    return sum;
}

// Per generator: the lattice value's weight, and the mean and scale of the scalar noise (the
// scale being POV-Ray's standard deviation over that of lattice_noise, 0.3529 with the value
// term and 0.2582 without). Generator 1's scale is the spread before its clip to [0, 1].
struct Generator {
    double value_weight, mean, scale;
};
constexpr Generator kGenerators[3] = {
    {0.65, 0.4803, 0.258 / 0.3529},
    {0.65, 0.5053, 0.1261 / 0.3529},
    {0.0, 0.4945, 0.1447 / 0.2582},
};
constexpr double kVectorScale = 0.2575 / 0.3529;

int octaves_taken(int octaves) { return std::clamp(octaves, 1, 10); }

const Generator& generator_of(int number) {
    return kGenerators[number >= 1 && number <= 3 ? number - 1 : kDefaultNoiseGenerator - 1];
}

}  // namespace

double solid_noise(Vec3 point, int generator) {
    const Generator& g = generator_of(generator);
    const double v = g.mean + g.scale * lattice_noise(point, g.value_weight, 0);
    return std::clamp(v, 0.0, 1.0);
}

Vec3 vector_noise(Vec3 point) {
    const double weight = generator_of(kDefaultNoiseGenerator).value_weight;
    return {kVectorScale * lattice_noise(point, weight, 1),
            kVectorScale * lattice_noise(point, weight, 2),
            kVectorScale * lattice_noise(point, weight, 3)};
}

Vec3 vector_turbulence(Vec3 point, int octaves, double omega, double lambda) {
    Vec3 sum;
    double amplitude = 1, frequency = 1;
    for (int octave = 0; octave < octaves_taken(octaves); ++octave) {
        sum = sum + amplitude * vector_noise(frequency * point);
        amplitude *= omega;
        frequency *= lambda;
    }
    return sum;
}

double scalar_turbulence(Vec3 point, int octaves, double omega, double lambda, int generator) {
    double sum = 0, amplitude = 1, frequency = 1;
    for (int octave = 0; octave < octaves_taken(octaves); ++octave) {
        sum += amplitude * solid_noise(frequency * point, generator);
        amplitude *= omega;
        frequency *= lambda;
    }
    return sum;
}

CellDistances cell_distances(Vec3 point, double metric, double offset) {
    constexpr double kFar = 1e300;
    CellDistances out{{kFar, kFar, kFar}, point};
    LatticeCell cell;
    if (!lattice_cell(point, cell)) return out;
    const double offset_power = std::pow(std::fabs(offset), metric);
    // The 27 cubes around the point's own hold its nearest three points but for rare corners.
    for (int64_t dx = -1; dx <= 1; ++dx)
        for (int64_t dy = -1; dy <= 1; ++dy)
            for (int64_t dz = -1; dz <= 1; ++dz) {
                const int64_t cx = cell.x + dx, cy = cell.y + dy, cz = cell.z + dz;
                auto uniform = [&](uint32_t channel) {
                    return lattice_hash(cx, cy, cz, channel) / 4294967296.0;
                };
                const Vec3 q{double(cx) + uniform(4), double(cy) + uniform(5),
                             double(cz) + uniform(6)};
                const Vec3 d = q - point;
                const double distance =
                    metric == 2 ? std::sqrt(dot(d, d) + offset_power)
                                : std::pow(std::pow(std::fabs(d.x), metric) +
                                               std::pow(std::fabs(d.y), metric) +
                                               std::pow(std::fabs(d.z), metric) + offset_power,
                                           1 / metric);
                // Into the three nearest, kept in order.
                int k = 3;
                for (; k > 0 && distance < out.nearest[k - 1]; --k)
                    if (k < 3) out.nearest[k] = out.nearest[k - 1];
                if (k < 3) out.nearest[k] = distance;
                if (k == 0) out.nearest_point = q;
            }
    return out;
}

}  // namespace rayset::tracer
