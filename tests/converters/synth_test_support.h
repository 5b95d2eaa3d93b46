// Shared by the synth, far-field and emit tests: adaptive quadrature (the brute-force truth the
// closed forms are checked against), statistical bounds, and rays held in memory.
#pragma once

#include "converters/analytic/analytic_sources.h"
#include "converters/photometry/farfield.h"
#include "converters/photometry/photometry.h"
#include "converters/rays/ray_stream.h"
#include "support/statistics.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <vector>

namespace rayset::test {

// Adaptive Gauss-Kronrod (7/15 points) integral of f over [a, b] to an absolute error of about
// `tolerance` (intervals are halved until the Gauss and Kronrod estimates agree).
inline double integrate(const std::function<double(double)>& f, double a, double b,
                        double tolerance, int depth = 0) {
    static const double x[8] = {
        0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
        0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
        0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
        0.207784955007898467600689403773245, 0.0};
    static const double wk[8] = {
        0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
        0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
        0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
        0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
    static const double wg[4] = {
        0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
        0.381830050505118944950369775488975, 0.417959183673469387755102040816327};
    const double mid = (a + b) / 2, half = (b - a) / 2;
    double kronrod = wk[7] * f(mid), gauss = wg[3] * f(mid);
    for (int i = 0; i < 7; ++i) {
        const double sum = f(mid - half * x[i]) + f(mid + half * x[i]);
        kronrod += wk[i] * sum;
        if (i % 2 == 1) gauss += wg[i / 2] * sum;
    }
    kronrod *= half;
    gauss *= half;
    // Below the rounding error of the sum no split helps; without this floor the recursion
    // would grow without bound wherever rounding exceeds the (halved) tolerance.
    const double error = std::abs(kronrod - gauss);
    if (error <= tolerance || error <= 1e-14 * std::abs(kronrod) || depth >= 30) return kronrod;
    return integrate(f, a, mid, tolerance / 2, depth + 1) +
           integrate(f, mid, b, tolerance / 2, depth + 1);
}

// The same over `pieces` equal parts: the adaptive error estimate can miss a kink in the
// integrand (where a clipped integration bound starts to bite), a fixed fine split cannot.
inline double integrate_pieces(const std::function<double(double)>& f, double a, double b,
                               int pieces, double tolerance) {
    double sum = 0;
    for (int k = 0; k < pieces; ++k)
        sum += integrate(f, a + (b - a) * k / pieces, a + (b - a) * (k + 1) / pieces,
                         tolerance / pieces);
    return sum;
}

// Cell counts of n rays against Multinomial(n, p_cell): each cell within Bernstein's bound at
// alpha = 1e-3 / cells (Bonferroni: all cells within together with probability >= 99.9% when
// the p are right), and chi-square over the cells expecting >= 5 rays (the rest pooled into
// one) against its 99.9% critical value (Wilson-Hilferty, z = 3.0902).
struct CountCheck {
    size_t bins = 0;          // cells with light expected
    size_t outside = 0;       // cells with no light expected but some measured
    size_t beyond_bound = 0;  // cells outside the Bernstein bound
    double worst_ratio = 0;   // largest |count - expected| / bound
    double chi_square = 0;
    size_t dof = 0;
    double critical = 0;
};

inline CountCheck check_counts(const std::vector<double>& p, const std::vector<double>& count,
                               double n) {
    CountCheck r;
    for (double pk : p) r.bins += pk > 0;
    const double alpha = 1e-3 / double(r.bins);
    double pooled_expected = 0, pooled_count = 0;
    size_t cells = 0;
    for (size_t k = 0; k < p.size(); ++k) {
        const double pk = p[k];
        if (pk <= 0) {
            r.outside += count[k] != 0;
            continue;
        }
        const double bound = bernstein_bound(n, pk, alpha), deviation = std::abs(count[k] - n * pk);
        r.worst_ratio = std::max(r.worst_ratio, deviation / bound);
        r.beyond_bound += deviation >= bound;
        if (n * pk < 5) {
            pooled_expected += n * pk;
            pooled_count += count[k];
        } else {
            r.chi_square += (count[k] - n * pk) * (count[k] - n * pk) / (n * pk);
            ++cells;
        }
    }
    if (pooled_expected > 0) {
        r.chi_square +=
            (pooled_count - pooled_expected) * (pooled_count - pooled_expected) / pooled_expected;
        ++cells;
    }
    r.dof = cells - 1;
    r.critical = chi_square_critical(double(r.dof), 3.0902);
    return r;
}

// A far field's polar caps (gamma 0 and 180) are one cell each, shared by the C planes: the
// values of per-cell vectors (cell k = h * vertical + v) of a cap row summed into its C 0 cell,
// the others zero.
inline void pool_caps(std::vector<double>& per_cell, size_t nc, size_t nv) {
    for (size_t v : {size_t(0), nv - 1}) {
        for (size_t h = 1; h < nc; ++h)
            per_cell[v] += per_cell[h * nv + v], per_cell[h * nv + v] = 0;
    }
}

// Rays per far-field cell (without the repeated 360 plane), cell k = h * vertical + v, from the
// flux of equal-flux rays, the polar caps pooled (pool_caps); `fractional` counts cells whose
// flux is not a whole number of rays.
inline std::vector<double> cell_counts(const FarField& far, const std::vector<double>& cell_flux,
                                       double ray_flux, size_t& fractional) {
    const Photometry& p = far.photometry;
    const size_t nc = p.horizontal_deg.size() - 1, nv = p.vertical_deg.size();
    std::vector<double> count(nc * nv);
    for (size_t h = 0; h < nc; ++h)
        for (size_t v = 0; v < nv; ++v) count[h * nv + v] = cell_flux[p.index(h, v)] / ray_flux;
    pool_caps(count, nc, nv);
    fractional = 0;
    for (double& c : count) {
        fractional += std::abs(c - std::round(c)) > 1e-6;
        c = std::round(c);
    }
    return count;
}

// Flux of `source` in every cell of `far`'s grid (cell k = h * vertical + v, the polar caps pooled)
// by quadrature of Photometry::intensity() over the cell, split at the source's grid angles and
// their mirror images so that the integrand is smooth on every piece.
inline std::vector<double> expected_cell_flux(const Photometry& source, const FarField& far) {
    constexpr double deg = 3.14159265358979323846 / 180;
    std::vector<double> c_nodes;
    for (double h : source.horizontal_deg)
        for (double image : {h, 180 - h, 180 + h, 360 - h})
            for (double shift : {-360.0, 0.0, 360.0}) c_nodes.push_back(image + shift);
    auto split = [](double lo, double hi, const std::vector<double>& nodes) {
        std::vector<double> cuts{lo, hi};
        for (double x : nodes)
            if (x > lo && x < hi) cuts.push_back(x);
        std::sort(cuts.begin(), cuts.end());
        return cuts;
    };
    const Photometry& p = far.photometry;
    const size_t nc = p.horizontal_deg.size() - 1, nv = p.vertical_deg.size();
    const double dc = p.horizontal_deg[1] - p.horizontal_deg[0],
                 dg = p.vertical_deg[1] - p.vertical_deg[0];
    std::vector<double> flux(nc * nv);
    for (size_t h = 0; h < nc; ++h)
        for (size_t v = 0; v < nv; ++v) {
            const auto cs =
                split(p.horizontal_deg[h] - dc / 2, p.horizontal_deg[h] + dc / 2, c_nodes);
            const auto gs = split(std::max(0.0, p.vertical_deg[v] - dg / 2),
                                  std::min(180.0, p.vertical_deg[v] + dg / 2), source.vertical_deg);
            double sum = 0;
            for (size_t a = 0; a + 1 < cs.size(); ++a)
                for (size_t b = 0; b + 1 < gs.size(); ++b) {
                    // Linear in C on the piece: the two-point Gauss rule is exact.
                    const double mid = (cs[a] + cs[a + 1]) / 2, half = (cs[a + 1] - cs[a]) / 2,
                                 off = half / std::sqrt(3.0);
                    auto in_gamma = [&](double g) {
                        return (source.intensity(mid - off, g) + source.intensity(mid + off, g)) *
                               half * std::sin(g * deg);
                    };
                    sum += integrate(in_gamma, gs[b], gs[b + 1], 1e-14) * deg * deg;
                }
            flux[h * nv + v] = sum;
        }
    pool_caps(flux, nc, nv);
    return flux;
}

// The mean of `source`'s closed-form intensity over cell (h, v) of a far field's grid
// (farfield.h; the polar caps over the whole circle): Gauss-Legendre, 8 x 8 points in C and
// cos(gamma).
inline double closed_form_cell_mean(const analytic::Source& source, const Photometry& p, size_t h,
                                    size_t v) {
    static const double x[8] = {-0.9602898564975363, -0.7966664774136267, -0.5255324099163290,
                                -0.1834346424956498, 0.1834346424956498,  0.5255324099163290,
                                0.7966664774136267,  0.9602898564975363};
    static const double w[8] = {0.1012285362903763, 0.2223810344533745, 0.3137066458778873,
                                0.3626837833783620, 0.3626837833783620, 0.3137066458778873,
                                0.2223810344533745, 0.1012285362903763};
    constexpr double deg = 3.14159265358979323846 / 180;
    const size_t nv = p.vertical_deg.size();
    const double dg = p.vertical_deg[1] - p.vertical_deg[0],
                 dc = p.horizontal_deg[1] - p.horizontal_deg[0];
    const bool cap = v == 0 || v + 1 == nv;
    const double g0 = v == 0 ? 0 : p.vertical_deg[v] - dg / 2,
                 g1 = v + 1 == nv ? 180 : p.vertical_deg[v] + dg / 2;
    const double mu0 = std::cos(g1 * deg), mu1 = std::cos(g0 * deg);
    const double c_mid = cap ? 180 : p.horizontal_deg[h], c_half = cap ? 180 : dc / 2;
    double sum = 0;
    for (int a = 0; a < 8; ++a)
        for (int b = 0; b < 8; ++b) {
            const double c = (c_mid + x[a] * c_half) * deg;
            const double mu = (mu0 + mu1) / 2 + x[b] * (mu1 - mu0) / 2,
                         r = std::sqrt(std::max(0.0, 1 - mu * mu));
            sum += w[a] * w[b] * source.intensity({r * std::cos(c), r * std::sin(c), mu});
        }
    return sum / 4;
}

// A decoder over rays held in memory, so far_field() can read what a test built.
class MemoryDecoder : public RayDecoder {
public:
    MemoryDecoder(const RayHeader& header, std::vector<Ray> rays) : rays_(std::move(rays)) {
        header_ = header;
        header_.ray_count = rays_.size();
    }
    bool decode(RayColumns& chunk, size_t max_rays) override {
        chunk.clear();
        chunk.first_index = next_;
        while (next_ < rays_.size() && chunk.size() < max_rays) chunk.push_back(rays_[next_++]);
        return chunk.size() > 0;
    }
    Location locate(uint64_t index) const override { return Location::byte(index * sizeof(Ray)); }

private:
    std::vector<Ray> rays_;
    size_t next_ = 0;
};

inline std::unique_ptr<RayReader> memory_reader(const RayHeader& header, std::vector<Ray> rays) {
    return std::make_unique<RayReader>(std::make_unique<MemoryDecoder>(header, std::move(rays)),
                                       "memory.rays", RayReadOptions{});
}

// An encoder that keeps what it is given.
class MemoryEncoder : public RayEncoder {
public:
    void write(const RayChunk& chunk) override {
        rays.insert(rays.end(), chunk.rays.begin(), chunk.rays.end());
    }
    void finish() override { finished = true; }
    std::vector<Ray> rays;
    bool finished = false;
};

}  // namespace rayset::test
