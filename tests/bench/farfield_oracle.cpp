// Oracle, for choosing a bandwidth rule: the far field at a ladder of fixed bandwidths, and per
// gamma row the one closest to the closed form (chosen with the truth, so no estimator can do
// better with one bandwidth per row). Usage: farfield_oracle SOURCE RAYS [KEY VALUE]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>
#include "converters/analytic/synth.h"
#include "converters/photometry/farfield.h"
#include "converters/synth_test_support.h"
using namespace rayset;

// Radiant flux only: the luminous column is not needed here.
SynthOptions radiant_only() {
    SynthOptions options;
    options.luminous = false;
    return options;
}

int main(int argc, char** argv) {
    auto source =
        make_source(argv[1], argc > 4 ? SourceParameters{{argv[3], argv[4]}} : SourceParameters{});
    uint64_t n = std::atof(argv[2]);
    test::MemoryEncoder out;
    synthesize(*source, n, 11, out, radiant_only());
    std::vector<double> sigmas = {1, 1.41, 2, 2.83, 4, 5.66, 8, 11.3, 16};
    std::vector<FarField> fields;
    for (double s : sigmas) {
        auto reader = test::memory_reader(synth_header(*source, n, 11, radiant_only()), out.rays);
        FarFieldOptions o;
        o.quantity = FarFieldQuantity::radiometric;
        o.smoothing = FarFieldSmoothing::fixed;
        o.smoothing_deg = s;
        fields.push_back(far_field(*reader, o));
    }
    const Photometry& p = fields[0].photometry;
    size_t nh = p.horizontal_deg.size() - 1, nv = p.vertical_deg.size();
    std::vector<double> truth(nh * nv), omega(nh * nv);
    double total = 0;
    for (size_t h = 0; h < nh; ++h)
        for (size_t v = 0; v < nv; ++v) {
            double c = p.horizontal_deg[h] * kRadiansPerDegree,
                   g = p.vertical_deg[v] * kRadiansPerDegree;
            truth[h * nv + v] = source->intensity({sin(g) * cos(c), sin(g) * sin(c), cos(g)});
            omega[h * nv + v] = fields[0].solid_angle[p.index(h, v)];
            total += truth[h * nv + v] * omega[h * nv + v];
        }
    std::vector<size_t> order(nh * nv);
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return truth[a] > truth[b]; });
    std::vector<char> in(nh * nv, 0);
    double acc = 0;
    for (size_t i : order) {
        if (acc >= 0.99 * total || truth[i] <= 0) break;
        acc += truth[i] * omega[i];
        in[i] = 1;
    }
    double fsq = 0, fw = 0;
    for (size_t v = 0; v < nv; ++v) {
        double best = 1e300;
        size_t bs = 0;
        for (size_t s = 0; s < sigmas.size(); ++s) {
            double sq = 0, w = 0;
            for (size_t h = 0; h < nh; ++h) {
                size_t i = h * nv + v;
                if (!in[i]) continue;
                double e = fields[s].photometry.candela[p.index(h, v)] / truth[i] - 1;
                sq += truth[i] * omega[i] * e * e;
                w += truth[i] * omega[i];
            }
            if (w > 0 && sq < best) best = sq, bs = s;
        }
        if (best < 1e300) {
            fsq += best;
            double w = 0;
            for (size_t h = 0; h < nh; ++h)
                if (in[h * nv + v]) w += truth[h * nv + v] * omega[h * nv + v];
            fw += w;
            if (v % 4 == 0)
                std::printf("gamma %5.1f best sigma %5.2f row flux-rms %.3f%%\n", p.vertical_deg[v],
                            sigmas[bs], 100 * std::sqrt(best / w));
        }
    }
    std::printf("oracle flux-weighted rms %.3f%%\n", 100 * std::sqrt(fsq / fw));
}
