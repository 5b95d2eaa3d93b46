// Far-field accuracy from a limited set of rays: RMS relative error of `rayconv farfield`'s
// estimates against the closed form, for analytic sources at several ray counts.
//
// Usage: farfield_accuracy [RAYS...]   (default 1e4 1e5 1e6 1e7)
//
// Sources: a Lambertian disk tilted 30 degrees against the polar axis (no symmetry about it),
// a cos^n lobe with n = 20 (half width at half maximum 15 degrees), and the untilted disk.
// Error: over the grid angles (5 x 2.5 degrees) in the directions that carry 99% of the flux
// (the brightest, taken in order of the closed-form intensity), the root of the solid-angle
// weighted mean of (estimate / closed form - 1)^2. Estimators: the histogram (smoothing
// none), kernel density with the bandwidth chosen per direction (auto), and the fraction of
// values whose closed form lies within 2 stated standard errors (95% if they are honest).
#include "converters/analytic/synth.h"
#include "converters/photometry/farfield.h"
#include "converters/synth_test_support.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numeric>
#include <string>
#include <vector>

using namespace rayset;

namespace {

// Radiant flux only: the luminous column is not needed here.
SynthOptions radiant_only() {
    SynthOptions options;
    options.luminous = false;
    return options;
}

struct Score {
    double rms = 0;       // relative, over the 99% region, weighted by solid angle
    double flux_rms = 0;  // the same weighted by the flux (closed-form intensity x solid angle)
    double covered = 0;   // fraction within 2 standard errors
    double seconds = 0;
    double flux_error = 0;
    double flux_scale = 1;  // the factor that kept the flux (FarField::flux_scale)
};

Score score(const analytic::Source& source, const FarField& f) {
    const Photometry& p = f.photometry;
    struct Node {
        double truth, estimate, se, omega;
    };
    std::vector<Node> nodes;
    double total = 0;
    for (size_t h = 0; h + 1 < p.horizontal_deg.size(); ++h)
        for (size_t v = 0; v < p.vertical_deg.size(); ++v) {
            const size_t at = p.index(h, v);
            nodes.push_back({test::closed_form_cell_mean(source, p, h, v), p.candela[at],
                             std::sqrt(f.variance[at]), f.solid_angle[at]});
            total += nodes.back().truth * nodes.back().omega;
        }
    std::sort(nodes.begin(), nodes.end(),
              [](const Node& a, const Node& b) { return a.truth > b.truth; });
    double flux = 0, weight = 0, square = 0, covered = 0, flux_square = 0;
    for (const Node& n : nodes) {
        if (flux >= 0.99 * total || n.truth <= 0) break;
        flux += n.truth * n.omega;
        const double e = n.estimate / n.truth - 1;
        weight += n.omega;
        square += n.omega * e * e;
        flux_square += n.truth * n.omega * e * e;
        covered += n.omega * (std::abs(n.estimate - n.truth) <= 2 * n.se ? 1 : 0);
    }
    Score s;
    s.rms = std::sqrt(square / weight);
    s.flux_rms = std::sqrt(flux_square / flux);
    s.covered = covered / weight;
    s.flux_error = f.total_flux / source.total_flux() - 1;
    s.flux_scale = f.flux_scale;
    return s;
}

Score run(const analytic::Source& source, uint64_t rays, FarFieldSmoothing smoothing) {
    test::MemoryEncoder out;
    synthesize(source, rays, 11, out, radiant_only());
    auto reader = test::memory_reader(synth_header(source, rays, 11, radiant_only()),
                                      std::move(out.rays));
    FarFieldOptions o;
    o.quantity = FarFieldQuantity::radiometric;
    o.smoothing = smoothing;
    const auto start = std::chrono::steady_clock::now();
    const FarField f = far_field(*reader, o);
    Score s = score(source, f);
    s.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return s;
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<uint64_t> counts;
    for (int i = 1; i < argc; ++i) counts.push_back(uint64_t(std::stod(argv[i])));
    if (counts.empty()) counts = {10000, 100000, 1000000, 10000000};
    const std::vector<std::pair<std::string, SourceParameters>> sources = {
        {"disk", {{"tilt", "30"}}}, {"lobe", {{"n", "20"}}}, {"disk", {}}};
    std::printf("%-14s %10s | %-30s | %-40s\n", "source", "rays", "histogram: rms  flux-rms in 2se",
                "smoothed: rms  flux-rms in 2se  seconds  flux  scale-1");
    for (const auto& [name, parameters] : sources) {
        const auto source = make_source(name, parameters);
        std::string label = name;
        for (const auto& [k, v] : parameters) label += " " + k + "=" + v;
        for (uint64_t n : counts) {
            const Score plain = run(*source, n, FarFieldSmoothing::none);
            const Score smooth = run(*source, n, FarFieldSmoothing::automatic);
            std::printf(
                "%-14s %10llu | %7.3f%% %7.3f%% %5.1f%% | %7.3f%% %7.3f%% %5.1f%%  %6.2f  %8.1e  "
                "%+8.1e\n",
                label.c_str(), (unsigned long long)n, 100 * plain.rms, 100 * plain.flux_rms,
                100 * plain.covered, 100 * smooth.rms, 100 * smooth.flux_rms, 100 * smooth.covered,
                smooth.seconds, smooth.flux_error, smooth.flux_scale - 1);
            std::fflush(stdout);
        }
    }
}
