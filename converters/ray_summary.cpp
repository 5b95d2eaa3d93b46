#include "converters/ray_summary.h"

#include "converters/spectrum.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace rayset {

namespace {

constexpr double kPi = 3.14159265358979323846;

// The azimuth is partitioned by the "diamond angle", a monotone stand-in for it in [0, 4) that
// costs one division instead of an atan2 per ray; each cell's solid angle is then computed from
// the true azimuths of its sector's edges, so coverage stays an exact share of the sphere.
double diamond_angle(double x, double y) {
    if (y >= 0) return x >= 0 ? y / (x + y) : 1 - x / (y - x);
    return x < 0 ? 2 - y / (-x - y) : 3 + x / (x - y);
}

// Azimuth (radians, 0..2pi) of a diamond angle.
double azimuth_of(double a) {
    int quadrant = std::min(3, static_cast<int>(a));
    double t = a - quadrant;  // the point (1 - t, t) of the quadrant, rotated
    return std::atan2(t, 1 - t) + quadrant * kPi / 2;
}

int coverage_cell(const Vec3f& d) {
    int band = std::clamp(static_cast<int>((d.z + 1) * 0.5 * RaySummary::kZBands), 0, RaySummary::kZBands - 1);
    int sector = 0;
    if (d.x != 0 || d.y != 0)
        sector = std::min(RaySummary::kPhiBands - 1, static_cast<int>(diamond_angle(d.x, d.y) * (RaySummary::kPhiBands / 4)));
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

}  // namespace

RaySummary summarise_rays(RayReader& reader, const std::function<void(double)>& progress) {
    RaySummary s;
    const RayHeader& header = reader.header();
    PhotometricWeights weights(header);
    const bool spectral_luminous = !header.has_luminous && weights.luminous_known();
    double luminous_from_spectrum = 0;
    double mean[3] = {0, 0, 0};
    std::vector<uint8_t> reached(RaySummary::kCoverageCells, 0);
    float lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    float wmin = INFINITY, wmax = -INFINITY;

    RayChunk chunk;
    while (reader.read(chunk)) {
        for (const Ray& r : chunk.rays) {
            const float o[3] = {r.origin.x, r.origin.y, r.origin.z};
            for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], o[k]), hi[k] = std::max(hi[k], o[k]);
            if (std::isnan(r.wavelength)) {
                if (header.spectral == SpectralKind::per_ray_wavelength) ++s.unknown_wavelength_rays;
            } else {
                wmin = std::min(wmin, r.wavelength);
                wmax = std::max(wmax, r.wavelength);
            }
            double w = header.has_radiant ? r.radiant : r.luminous;
            mean[0] += w * r.direction.x, mean[1] += w * r.direction.y, mean[2] += w * r.direction.z;
            reached[coverage_cell(r.direction)] = 1;
            if (spectral_luminous) {
                double lm = weights.luminous(r);
                if (std::isfinite(lm)) luminous_from_spectrum += lm;
            }
        }
        if (progress) progress(reader.progress());
    }
    const RayTotals& t = reader.totals();
    s.rays = t.rays;
    s.radiant = t.radiant;
    s.luminous = t.luminous;
    s.zero_flux_rays = t.zero_flux_rays;
    if (spectral_luminous) s.luminous_from_spectrum = luminous_from_spectrum;
    s.min_origin = {lo[0], lo[1], lo[2]};
    s.max_origin = {hi[0], hi[1], hi[2]};
    if (wmin <= wmax) s.min_wavelength = wmin, s.max_wavelength = wmax;
    if (header.spectral == SpectralKind::single_wavelength) s.min_wavelength = s.max_wavelength = header.single_wavelength;

    double norm = std::sqrt(mean[0] * mean[0] + mean[1] * mean[1] + mean[2] * mean[2]);
    Vec3f axis = norm > 0 ? Vec3f{float(mean[0] / norm), float(mean[1] / norm), float(mean[2] / norm)} : Vec3f{0, 0, 1};
    s.mean_direction = axis;
    double reached_solid_angle = 0;
    double min_cos = 1;
    for (int c = 0; c < RaySummary::kCoverageCells; ++c) {
        if (!reached[c]) continue;
        reached_solid_angle += cell_solid_angle(c);
        Vec3f v = cell_centre(c);
        min_cos = std::min(min_cos, double(v.x) * axis.x + double(v.y) * axis.y + double(v.z) * axis.z);
    }
    s.sphere_coverage = reached_solid_angle / (4 * kPi);
    s.max_angle_from_mean_deg = std::acos(std::clamp(min_cos, -1.0, 1.0)) * 180 / kPi;
    return s;
}

}  // namespace rayset
