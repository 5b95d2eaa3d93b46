#include "lightmodel/diagram_estimate.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace rayset::lightmodel {

namespace {

constexpr int kProbeBands = 20, kProbeSectors = 24;
// A local fit's estimate over the kernel's, applied to every cell, at most this: beyond it the
// kernel's estimate is too near zero for the ratio to mean anything.
constexpr double kMaxCorrection = 4;
constexpr int kMinBands = GoniometricDiagram::kDefaultBands, kMaxBands = 256;
constexpr int kMinSectors = GoniometricDiagram::kDefaultSectors, kMaxSectors = 512;

// The flux-weighted lower quartile of the bandwidths chosen at the probe directions (degrees).
double grid_bandwidth(const DirectionHistogram& rays) {
    const GoniometricDiagram probes(kProbeBands, kProbeSectors);
    std::vector<std::pair<double, double>> sigma_weight;  // probes share one solid angle
    double total = 0;
    for (int cell = 0; cell < probes.cell_count(); ++cell) {
        const Vec3 w = probes.cell_centre(cell);
        const DirectionHistogram::Estimate e = rays.adaptive(w.x, w.y, w.z);
        if (!(e.intensity > 0)) continue;
        sigma_weight.push_back({e.sigma_deg, e.intensity});
        total += e.intensity;
    }
    if (sigma_weight.empty()) return DiagramEstimate::kResolution.max_sigma_deg;
    std::sort(sigma_weight.begin(), sigma_weight.end());
    double below = 0;
    for (const auto& [sigma, weight] : sigma_weight)
        if ((below += weight) >= 0.25 * total) return sigma;
    return sigma_weight.back().first;
}

}  // namespace

DiagramEstimate::DiagramEstimate(size_t cells) : cells_(cells) {}

void DiagramEstimate::add(size_t cell, Vec3 w, double flux) {
    if (!cells_[cell]) cells_[cell] = std::make_unique<DirectionHistogram>(kResolution);
    cells_[cell]->add(w.x, w.y, w.z, flux);
}

std::vector<GoniometricDiagram> DiagramEstimate::diagrams(const std::vector<size_t>& wanted,
                                                          int bands, int sectors) {
    DirectionHistogram all(kAllRays);
    for (const std::unique_ptr<DirectionHistogram>& rays : cells_)
        if (rays) all.merge(*rays);
    all.prepare();
    if (bands <= 0 || sectors <= 0) {
        const double step = grid_bandwidth(all) / 3 * kPi / 180;  // radians at the horizon
        bands = std::clamp(2 * int(std::ceil(1 / step)), kMinBands, kMaxBands);
        sectors = std::clamp(int(std::ceil(2 * kPi / step)), kMinSectors, kMaxSectors);
    }
    const GoniometricDiagram grid(bands, sectors);
    std::vector<Vec3> centre(size_t(grid.cell_count()));
    std::vector<double> sigma(centre.size()), correction(centre.size(), 1.0);
    tbb::parallel_for(size_t(0), centre.size(), [&](size_t c) {
        const Vec3 w = centre[c] = grid.cell_centre(int(c));
        const DirectionHistogram::Estimate chosen = all.adaptive(w.x, w.y, w.z);
        sigma[c] = chosen.sigma_deg;
        if (chosen.local()) {
            const double kernel = all.at(w.x, w.y, w.z, chosen.sigma_deg).intensity;
            if (kernel > 0)
                correction[c] = std::clamp(chosen.intensity / kernel, 0.0, kMaxCorrection);
        }
    });

    std::vector<GoniometricDiagram> out(wanted.size());
    tbb::parallel_for(size_t(0), wanted.size(), [&](size_t k) {
        std::vector<double> density(centre.size(), 0.0);
        double total = 0;
        if (std::unique_ptr<DirectionHistogram>& rays = cells_[wanted[k]]) {
            rays->prepare();
            total = rays->total_flux();
            for (size_t c = 0; total > 0 && c < centre.size(); ++c)
                density[c] =
                    std::max(0.0,
                             rays->at(centre[c].x, centre[c].y, centre[c].z, sigma[c]).intensity) *
                    correction[c] / total;
            rays.reset();
        }
        out[k] = GoniometricDiagram::from_densities(bands, sectors, total, density);
    });
    return out;
}

}  // namespace rayset::lightmodel
