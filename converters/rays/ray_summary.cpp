#include "converters/rays/ray_summary.h"

#include "converters/colour/spectrum.h"
#include "converters/rays/simd.h"
#include "core/geometry.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <numeric>
#include <optional>
#include <vector>

namespace rayset {

namespace {

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

// A cell is numbered band << 8 | sector: a shift instead of a multiplication by kPhiBands
// (SSE2 has no 32-bit vector multiply); numbers whose sector is kPhiBands or more are unused.
constexpr int kSectorBits = 8;
static_assert(RaySummary::kPhiBands <= 1 << kSectorBits);
constexpr int kCellNumbers = RaySummary::kZBands << kSectorBits,
              kSectorMask = (1 << kSectorBits) - 1;

// The band and the sector as floats clamped to their ranges before they are truncated: a
// minimum and a maximum, written as the comparisons SSE's minps and maxps make (a NaN band
// goes to 0), instead of a clamp in integers, which SSE2 does in four instructions.
constexpr float kTopBand = RaySummary::kZBands - 0.5f, kTopSector = RaySummary::kPhiBands - 0.5f;

double sector_azimuth(int sector, double within) {
    return azimuth_of((sector + within) * 4.0 / RaySummary::kPhiBands);
}

// What the cells of a sector share: the width of its azimuths and the direction of their middle
// (a table of sectors, so that the reached cells cost no atan2 each).
struct Sectors {
    double width[RaySummary::kPhiBands], cos_middle[RaySummary::kPhiBands],
        sin_middle[RaySummary::kPhiBands];

    Sectors() {
        for (int sector = 0; sector < RaySummary::kPhiBands; ++sector) {
            const double from = sector_azimuth(sector, 0), to = sector_azimuth(sector, 1),
                         middle = 0.5 * (from + to);
            width[sector] = to - from, cos_middle[sector] = std::cos(middle),
            sin_middle[sector] = std::sin(middle);
        }
    }
    double solid_angle(int cell) const {
        return 2.0 / RaySummary::kZBands * width[cell & kSectorMask];
    }
    Vec3f centre(int cell) const {
        const int band = cell >> kSectorBits, sector = cell & kSectorMask;
        const double z = (band + 0.5) / RaySummary::kZBands * 2 - 1,
                     s = std::sqrt(std::max(0.0, 1 - z * z));
        return {float(s * cos_middle[sector]), float(s * sin_middle[sector]), float(z)};
    }
};

// Vectors of four lanes (GCC's vector extensions, which compile to SSE2 on any x86-64). Four
// rays are taken at a time: every per-ray step below is one vector operation for the four.
using V4f = float __attribute__((vector_size(16)));
using V4i = int32_t __attribute__((vector_size(16)));
using V4d = double __attribute__((vector_size(32)));  // two registers; never passed to a call
#pragma GCC diagnostic ignored "-Wpsabi"  // GCC's note on passing 32-byte vectors by value

RAYSET_ALWAYS_INLINE V4f load4(const float* p) {
    V4f v;
    std::memcpy(&v, p, sizeof v);
    return v;
}
RAYSET_ALWAYS_INLINE V4f splat(float v) { return V4f{v, v, v, v}; }

// The cells of four directions, in float. Branch-free: directions fall in the four quadrants at
// random, so branches on them would mostly be mispredicted. The quadrant's boundaries take -0
// as 0; (0, 0) is sector 0 (the smallest normal float is at most a sum that is not 0, so it
// gives 0 / min).
RAYSET_ALWAYS_INLINE V4i coverage_cells(V4f x, V4f y, V4f z) {
    V4f band = (z + 1.0f) * (0.5f * RaySummary::kZBands);
    band = band > 0.0f ? band : 0.0f;
    band = band < kTopBand ? band : kTopBand;
    const V4f ax = (V4f)((V4i)x & INT32_MAX), ay = (V4f)((V4i)y & INT32_MAX);  // |x|, |y|
    const V4i odd = (y >= 0) != (x >= 0);                                      // masks: -1 or 0
    const V4i quadrant = ((y < 0) & 2) | (odd & 1);
    const V4f sum = ax + ay, smallest = splat(std::numeric_limits<float>::min());
    const V4f part = (odd ? ax : ay) / (sum > smallest ? sum : smallest);
    V4f sector = (__builtin_convertvector(quadrant, V4f) + part) * float(RaySummary::kPhiBands / 4);
    sector = sector < kTopSector ? sector : kTopSector;
    return __builtin_convertvector(band, V4i) << kSectorBits |
           __builtin_convertvector(sector, V4i);  // truncated
}

// Sums kept in kLanes lanes: ray i of a block goes to lane i % kLanes (a block's last rays
// past a multiple of kLanes to lane 0), so a sum is the same however the loop is compiled; it
// depends on the blocks, which follow the chunks and parts, which the file alone decides. Eight
// lanes are two vectors of four, whose additions do not wait for each other.
constexpr size_t kLanes = 8;
struct LaneSums {
    double v[kLanes] = {};
    double total() const { return std::accumulate(v, v + kLanes, 0.0); }
    void add(const LaneSums& other) {
        for (size_t l = 0; l < kLanes; ++l) v[l] += other.v[l];
    }
};

// The running state of the summary of one part of a file; parts are merged in file order.
class Accumulator {
public:
    Accumulator(const RayHeader& header, SummaryKernel kernel) : header_(header), weights_(header) {
        avx2_ = kernel == SummaryKernel::fastest && cpu_has_avx2();
        spectral_luminous_ = !header.has_luminous && weights_.luminous_known();
        shared_efficacy_ = weights_.shared_efficacy();
    }

    void add(const RayColumns& chunk) {
        const size_t n = chunk.size();
        const float* weight = header_.has_radiant ? chunk.radiant.data() : chunk.luminous.data();
        // Only per-ray wavelengths are worth their extremes; otherwise the column is unknown.
        const bool wavelengths = header_.spectral == SpectralKind::per_ray_wavelength;
        for (size_t start = 0; start < n; start += kBlock) {
            const size_t block = std::min(kBlock, n - start);
#if RAYSET_HAVE_AVX2_TARGET
            if (avx2_) {
                if (wavelengths)
                    add_block_avx2<true>(chunk, weight, start, block);
                else
                    add_block_avx2<false>(chunk, weight, start, block);
                continue;
            }
#endif
            if (wavelengths)
                add_block<true>(chunk, weight, start, block);
            else
                add_block<false>(chunk, weight, start, block);
        }
        if (spectral_luminous_ && !shared_efficacy_)
            for (size_t i = 0; i < n; ++i) {
                const double lm = weights_.luminous(chunk.ray(i));
                if (std::isfinite(lm)) luminous_from_spectrum_ += lm;
            }
    }

    // The part that comes after this one in the file.
    void merge(const Accumulator& next) {
        for (int k = 0; k < 4; ++k) {
            low_[k] = next.low_[k] < low_[k] ? next.low_[k] : low_[k];
            high_[k] = next.high_[k] > high_[k] ? next.high_[k] : high_[k];
        }
        for (int k = 0; k < 3; ++k) mean_[k].add(next.mean_[k]);
        unknown_ += next.unknown_;
        luminous_from_spectrum_ += next.luminous_from_spectrum_;
        for (size_t c = 0; c < reached_.size(); ++c) reached_[c] |= next.reached_[c];
    }

    void finish(const RayTotals& totals, RaySummary& s) const;

private:
    // Up to kBlock rays from `start`, whose cells fit an array on the stack; direction sums are
    // kept in float for kGroup rays at a time.
    static constexpr size_t kBlock = 512, kGroup = 64;

#if RAYSET_HAVE_AVX2_TARGET
    // add_block() compiled for AVX2 (converters/rays/simd.h): its three-operand forms and blends
    // take about a quarter less time.
    template <bool kWavelength>
    RAYSET_TARGET_AVX2 void add_block_avx2(const RayColumns& c, const float* weight, size_t start,
                                           size_t n) {
        add_block<kWavelength>(c, weight, start, n);
    }
#endif

    // Fields 0-2 are the origin, 3 the wavelength (extremes and unknowns kept only if asked:
    // a register less in a loop that has few to spare).
    template <bool kWavelength>
    RAYSET_ALWAYS_INLINE void add_block(const RayColumns& c, const float* weight, size_t start,
                                        size_t n) {
        constexpr int kFields = kWavelength ? 4 : 3;
        const float* field[4] = {c.ox.data() + start, c.oy.data() + start, c.oz.data() + start,
                                 c.wavelength.data() + start};
        const float *dx = c.dx.data() + start, *dy = c.dy.data() + start, *dz = c.dz.data() + start;
        weight += start;
        V4i unknown = {};
        alignas(16) int32_t cells[kBlock];
        // Locals: the byte stores to `seen` could alias members, which would then be reloaded.
        V4f low[4], high[4];
        std::copy(low_, low_ + 4, low), std::copy(high_, high_ + 4, high);
        uint8_t* const seen = reached_.data();
        size_t i = 0;
        const size_t vectorised = n - n % kLanes;
        while (i < vectorised) {
            // Flux-weighted direction sums of up to kGroup rays, in float: a lane adds at most
            // kGroup / kLanes = 8 products, so its sum is within 9 u_f of the sum of their absolute
            // values (Higham 4.2, with the products' own rounding; u_f = 2^-24), at a third of the
            // instructions of sums in double. The groups' sums are added in double.
            V4f mean[3][2] = {};
            for (const size_t end = std::min(vectorised, i + kGroup); i < end; i += kLanes)
                for (size_t h = 0, j = i; h < 2; ++h, j += 4) {
                    // Extremes: a NaN leaves them as they are (the comparison is false).
                    for (int k = 0; k < kFields; ++k) {
                        const V4f v = load4(field[k] + j);
                        low[k] = v < low[k] ? v : low[k];
                        high[k] = v > high[k] ? v : high[k];
                    }
                    if constexpr (kWavelength) {
                        const V4f wavelength = load4(field[3] + j);
                        unknown -= wavelength != wavelength;  // -1 per NaN
                    }
                    const V4f x = load4(dx + j), y = load4(dy + j), z = load4(dz + j);
                    const V4f w = load4(weight + j);
                    mean[0][h] += w * x, mean[1][h] += w * y, mean[2][h] += w * z;
                    const V4i cell = coverage_cells(x, y, z);
                    std::memcpy(cells + j, &cell, sizeof cell);
                }
            for (int k = 0; k < 3; ++k)
                for (int h = 0; h < 2; ++h) {
                    V4d sum;
                    std::memcpy(&sum, mean_[k].v + 4 * h, sizeof sum);
                    sum += __builtin_convertvector(mean[k][h], V4d);
                    std::memcpy(mean_[k].v + 4 * h, &sum, sizeof sum);
                }
        }
        // The scattered stores after the vector loop: a store per lane from inside it would first
        // have to take the lane out of its register.
        for (size_t c = 0; c < i; ++c) seen[cells[c]] = 1;
        std::copy(low, low + 4, low_), std::copy(high, high + 4, high_);
        // The rays past the last multiple of kLanes: their cells by the same vector function, from
        // copies padded with the last ray (which marks its cell again), the rest one by one.
        if (i < n) {
            alignas(16) float tail[3][kLanes];
            for (size_t t = 0; t < kLanes; ++t) {
                const size_t r = std::min(i + t, n - 1);
                tail[0][t] = dx[r], tail[1][t] = dy[r], tail[2][t] = dz[r];
            }
            for (size_t t = 0; t < n - i; t += 4) {
                const V4i cell =
                    coverage_cells(load4(tail[0] + t), load4(tail[1] + t), load4(tail[2] + t));
                for (int l = 0; l < 4; ++l) seen[cell[l]] = 1;
            }
        }
        for (; i < n; ++i) {
            for (int k = 0; k < kFields; ++k) {
                const float v = field[k][i];
                low_[k][0] = v < low_[k][0] ? v : low_[k][0];
                high_[k][0] = v > high_[k][0] ? v : high_[k][0];
            }
            if constexpr (kWavelength) unknown[0] += std::isnan(field[3][i]);
            mean_[0].v[0] += double(weight[i]) * dx[i], mean_[1].v[0] += double(weight[i]) * dy[i];
            mean_[2].v[0] += double(weight[i]) * dz[i];
        }
        unknown_ += uint64_t(unknown[0]) + uint64_t(unknown[1]) + uint64_t(unknown[2]) +
                    uint64_t(unknown[3]);
    }

    static float lowest(V4f v) { return std::min({v[0], v[1], v[2], v[3]}); }
    static float highest(V4f v) { return std::max({v[0], v[1], v[2], v[3]}); }

    const RayHeader& header_;
    PhotometricWeights weights_;
    bool avx2_ = false;
    bool spectral_luminous_ = false;
    std::optional<double> shared_efficacy_;
    double luminous_from_spectrum_ = 0;  // when the efficacy differs from ray to ray
    LaneSums mean_[3];
    // Lane-wise extremes of origin x, y, z and wavelength.
    V4f low_[4] = {splat(INFINITY), splat(INFINITY), splat(INFINITY), splat(INFINITY)};
    V4f high_[4] = {splat(-INFINITY), splat(-INFINITY), splat(-INFINITY), splat(-INFINITY)};
    uint64_t unknown_ = 0;
    std::vector<uint8_t> reached_ = std::vector<uint8_t>(kCellNumbers, 0);
};

void Accumulator::finish(const RayTotals& t, RaySummary& s) const {
    s.rays = t.rays;
    s.radiant = t.radiant;
    s.luminous = t.luminous;
    s.zero_flux_rays = t.zero_flux_rays;
    if (spectral_luminous_) {
        // One efficacy for every ray: the sum of radiant x efficacy is the efficacy times the
        // radiant total, which the reader has summed already.
        if (!shared_efficacy_)
            s.luminous_from_spectrum = luminous_from_spectrum_;
        else
            s.luminous_from_spectrum =
                std::isfinite(*shared_efficacy_) ? *shared_efficacy_ * t.radiant : 0;
    }
    s.min_origin = {lowest(low_[0]), lowest(low_[1]), lowest(low_[2])};
    s.max_origin = {highest(high_[0]), highest(high_[1]), highest(high_[2])};
    if (header_.spectral == SpectralKind::per_ray_wavelength) s.unknown_wavelength_rays = unknown_;
    const float wmin = lowest(low_[3]), wmax = highest(high_[3]);
    if (wmin <= wmax) s.min_wavelength = wmin, s.max_wavelength = wmax;
    if (header_.spectral == SpectralKind::single_wavelength)
        s.min_wavelength = s.max_wavelength = header_.single_wavelength;

    const double mean[3] = {mean_[0].total(), mean_[1].total(), mean_[2].total()};
    double norm = std::sqrt(mean[0] * mean[0] + mean[1] * mean[1] + mean[2] * mean[2]);
    Vec3f axis = norm > 0
                     ? Vec3f{float(mean[0] / norm), float(mean[1] / norm), float(mean[2] / norm)}
                     : Vec3f{0, 0, 1};
    s.mean_direction = axis;
    const Sectors sectors;
    double reached_solid_angle = 0;
    double min_cos = 1;
    for (int c = 0; c < kCellNumbers; ++c) {
        if (!reached_[c]) continue;
        reached_solid_angle += sectors.solid_angle(c);
        Vec3f v = sectors.centre(c);
        min_cos =
            std::min(min_cos, double(v.x) * axis.x + double(v.y) * axis.y + double(v.z) * axis.z);
    }
    s.sphere_coverage = reached_solid_angle / (4 * kPi);
    s.max_angle_from_mean_deg = std::acos(std::clamp(min_cos, -1.0, 1.0)) * 180 / kPi;
}

}  // namespace

RaySummary summarise_rays(RayReader& reader, const std::function<void(double)>& progress,
                          SummaryKernel kernel) {
    // One accumulator per part of the file (read on as many threads), merged in file order:
    // the sums do not depend on which thread read what.
    std::vector<std::unique_ptr<Accumulator>> parts;
    for (size_t p = 0; p < reader.parts(); ++p)
        parts.push_back(std::make_unique<Accumulator>(reader.header(), kernel));
    reader.read_in_parts([&](size_t part, const RayColumns& chunk) { parts[part]->add(chunk); },
                         progress);
    for (size_t p = 1; p < parts.size(); ++p) parts[0]->merge(*parts[p]);
    RaySummary s;
    parts[0]->finish(reader.totals(), s);
    return s;
}

}  // namespace rayset
