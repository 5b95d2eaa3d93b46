#include "converters/ray_summary.h"

#include "converters/spectrum.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>
#include <vector>

namespace rayset {

namespace {

constexpr double kPi = 3.14159265358979323846;

// The azimuth is partitioned by the "diamond angle", a monotone stand-in for it in [0, 4) that
// costs one division instead of an atan2 per ray: in quadrant q (counted anticlockwise from
// +x, +y) it is q + |y| / (|x| + |y|) for even q and q + |x| / (|x| + |y|) for odd q. Each
// cell's solid angle is computed from the true azimuths of its sector's edges, so coverage
// stays an exact share of the sphere.

// Azimuth (radians, 0..2pi) of a diamond angle.
double azimuth_of(double a) {
    int quadrant = std::min(3, static_cast<int>(a));
    double t = a - quadrant;  // the point (1 - t, t) of the quadrant, rotated
    return std::atan2(t, 1 - t) + quadrant * kPi / 2;
}

// Branch-free: directions fall in the four quadrants at random, so branches on them would
// mostly be mispredicted. The quadrant's boundaries take -0 as 0; (0, 0) is sector 0.
inline int coverage_cell(float x, float y, float z) {
    const int band = std::clamp(static_cast<int>((z + 1) * 0.5 * RaySummary::kZBands), 0, RaySummary::kZBands - 1);
    const double ax = std::abs(double(x)), ay = std::abs(double(y)), sum = ax + ay;
    const int quadrant = 2 * (y < 0) + ((y >= 0) != (x >= 0));  // 0 1 2 3 anticlockwise from +x +y
    // The smallest normal double is below any sum of two floats but 0, where it gives 0 / min.
    const double part = ((quadrant & 1) ? ax : ay) / std::max(sum, std::numeric_limits<double>::min());
    const int sector = std::min(RaySummary::kPhiBands - 1, static_cast<int>((quadrant + part) * (RaySummary::kPhiBands / 4)));
    return band * RaySummary::kPhiBands + sector;
}

double sector_azimuth(int sector, double within) { return azimuth_of((sector + within) * 4.0 / RaySummary::kPhiBands); }

double cell_solid_angle(int cell) {
    int sector = cell % RaySummary::kPhiBands;
    return 2.0 / RaySummary::kZBands * (sector_azimuth(sector, 1) - sector_azimuth(sector, 0));
}

Vec3f cell_centre(int cell) {
    int band = cell / RaySummary::kPhiBands, sector = cell % RaySummary::kPhiBands;
    double z = (band + 0.5) / RaySummary::kZBands * 2 - 1;
    double phi = 0.5 * (sector_azimuth(sector, 0) + sector_azimuth(sector, 1));
    double s = std::sqrt(std::max(0.0, 1 - z * z));
    return {float(s * std::cos(phi)), float(s * std::sin(phi)), float(z)};
}

// The rays are taken kBlock at a time (the chunk's columns are contiguous floats, which the
// loops below vectorise over); 512 rays keep a block's columns in L1.
constexpr size_t kBlock = 512;

// Minimum and maximum of a field, kept position by position within the blocks and combined at
// the end: updating them is a loop of independent elements, which the compiler vectorises (a
// single running minimum it will not, as reordering could change the result). The comparisons
// are written so that a NaN value leaves them as they are.
struct Extremes {
    alignas(64) float lo[kBlock], hi[kBlock];

    Extremes() { std::fill(lo, lo + kBlock, INFINITY), std::fill(hi, hi + kBlock, -INFINITY); }
    void add(const float* values, size_t n) {
        for (size_t i = 0; i < n; ++i) {
            lo[i] = values[i] < lo[i] ? values[i] : lo[i];
            hi[i] = values[i] > hi[i] ? values[i] : hi[i];
        }
    }
    float min() const { return *std::min_element(lo, lo + kBlock); }
    float max() const { return *std::max_element(hi, hi + kBlock); }
};

// Sums kept in kLanes lanes, for the same reason.
constexpr size_t kLanes = 8;
struct LaneSums {
    double v[kLanes] = {};
    double total() const { return std::accumulate(v, v + kLanes, 0.0); }
};

// The running state of one summary pass.
struct Accumulator {
    explicit Accumulator(const RayHeader& header) : header(header), weights(header) {
        spectral_luminous = !header.has_luminous && weights.luminous_known();
        shared_efficacy = weights.shared_efficacy();
    }

    void add(const RayColumns& chunk) {
        const size_t n = chunk.size();
        const float* weight = header.has_radiant ? chunk.radiant.data() : chunk.luminous.data();
        for (size_t start = 0; start < n; start += kBlock) {
            const size_t count = std::min(kBlock, n - start);
            const float* direction[3] = {chunk.dx.data() + start, chunk.dy.data() + start, chunk.dz.data() + start};
            origin[0].add(chunk.ox.data() + start, count), origin[1].add(chunk.oy.data() + start, count);
            origin[2].add(chunk.oz.data() + start, count);
            add_block(direction, weight + start, chunk.wavelength.data() + start, count);
            if (spectral_luminous && !shared_efficacy)
                for (size_t i = start; i < start + count; ++i) {
                    const double lm = weights.luminous(chunk.ray(i));
                    if (std::isfinite(lm)) luminous_from_spectrum += lm;
                }
        }
    }

    void add_block(const float* const direction[3], const float* weight, const float* wavelengths, size_t n) {
        // NaN wavelengths are "unknown": counted where the file promises wavelengths, and skipped.
        if (header.spectral == SpectralKind::per_ray_wavelength)
            for (size_t i = 0; i < n; ++i) unknown += std::isnan(wavelengths[i]);
        wavelength.add(wavelengths, n);
        // Flux-weighted direction sums, in double.
        for (int k = 0; k < 3; ++k) {
            const float* d = direction[k];
            LaneSums sums = mean[k];  // a local: `d` might alias it as far as the compiler knows
            size_t i = 0;
            for (; i + kLanes <= n; i += kLanes)
                for (size_t l = 0; l < kLanes; ++l) sums.v[l] += double(weight[i + l]) * d[i + l];
            for (; i < n; ++i) sums.v[0] += double(weight[i]) * d[i];
            mean[k] = sums;
        }
        // The cells first (a loop the compiler vectorises), then the scattered stores.
        const float *dx = direction[0], *dy = direction[1], *dz = direction[2];
        for (size_t i = 0; i < n; ++i) cell[i] = coverage_cell(dx[i], dy[i], dz[i]);
        uint8_t* const seen = reached.data();  // a local: stores of bytes would force reloads of a member
        for (size_t i = 0; i < n; ++i) seen[cell[i]] = 1;
    }

    const RayHeader& header;
    PhotometricWeights weights;
    bool spectral_luminous = false;
    std::optional<double> shared_efficacy;
    double luminous_from_spectrum = 0;  // when the efficacy differs from ray to ray
    alignas(64) int32_t cell[kBlock];
    LaneSums mean[3];
    std::vector<uint8_t> reached = std::vector<uint8_t>(RaySummary::kCoverageCells, 0);
    Extremes origin[3];  // x, y, z
    Extremes wavelength;
    uint64_t unknown = 0;
};

}  // namespace

RaySummary summarise_rays(RayReader& reader, const std::function<void(double)>& progress) {
    RaySummary s;
    const RayHeader& header = reader.header();
    Accumulator a(header);
    RayColumns chunk;
    while (reader.read(chunk)) {
        a.add(chunk);
        if (progress) progress(reader.progress());
    }
    const RayTotals& t = reader.totals();
    s.rays = t.rays;
    s.radiant = t.radiant;
    s.luminous = t.luminous;
    s.zero_flux_rays = t.zero_flux_rays;
    if (a.spectral_luminous) {
        // One efficacy for every ray: the sum of radiant x efficacy is the efficacy times the
        // radiant total, which the reader has summed already.
        if (!a.shared_efficacy) s.luminous_from_spectrum = a.luminous_from_spectrum;
        else s.luminous_from_spectrum = std::isfinite(*a.shared_efficacy) ? *a.shared_efficacy * t.radiant : 0;
    }
    s.min_origin = {a.origin[0].min(), a.origin[1].min(), a.origin[2].min()};
    s.max_origin = {a.origin[0].max(), a.origin[1].max(), a.origin[2].max()};
    if (header.spectral == SpectralKind::per_ray_wavelength) s.unknown_wavelength_rays = a.unknown;
    const float wmin = a.wavelength.min(), wmax = a.wavelength.max();
    if (wmin <= wmax) s.min_wavelength = wmin, s.max_wavelength = wmax;
    if (header.spectral == SpectralKind::single_wavelength) s.min_wavelength = s.max_wavelength = header.single_wavelength;

    const double mean[3] = {a.mean[0].total(), a.mean[1].total(), a.mean[2].total()};
    double norm = std::sqrt(mean[0] * mean[0] + mean[1] * mean[1] + mean[2] * mean[2]);
    Vec3f axis = norm > 0 ? Vec3f{float(mean[0] / norm), float(mean[1] / norm), float(mean[2] / norm)} : Vec3f{0, 0, 1};
    s.mean_direction = axis;
    double reached_solid_angle = 0;
    double min_cos = 1;
    for (int c = 0; c < RaySummary::kCoverageCells; ++c) {
        if (!a.reached[c]) continue;
        reached_solid_angle += cell_solid_angle(c);
        Vec3f v = cell_centre(c);
        min_cos = std::min(min_cos, double(v.x) * axis.x + double(v.y) * axis.y + double(v.z) * axis.z);
    }
    s.sphere_coverage = reached_solid_angle / (4 * kPi);
    s.max_angle_from_mean_deg = std::acos(std::clamp(min_cos, -1.0, 1.0)) * 180 / kPi;
    return s;
}

}  // namespace rayset
