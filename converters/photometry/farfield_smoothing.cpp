#include "converters/photometry/farfield_smoothing.h"

#include "converters/analytic/analytic_geometry.h"
#include "core/geometry.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace rayset {

namespace {

// Kernels are cut where the wider of the two vMF densities has fallen to exp(-9) of its peak:
// what lies beyond holds about 1e-4 of its weight.
constexpr double kCutoffSigmas = 6;
// The local fit's Gaussian weight is cut at 5 sigma (exp(-12.5) of its peak).
constexpr double kLocalCutoffSigmas = 5;
// A moment covariance below 1e-6 sigma^4 in determinant: the rays near u lie on a line or a
// point, and no quadratic can be fitted to them.
constexpr double kMinCovarianceRatio = 1e-6;
// How many standard errors of noise the bandwidth rule allows for (2: best of 1, 1.5, 2, 2.5
// and 3 on the analytic sources of tests/bench/farfield_accuracy).
constexpr double kMargin = 2;

// The normalised von Mises-Fisher density on the unit sphere at cos(angle) t is
// kappa / (2 pi (1 - exp(-2 kappa))) exp(kappa (t - 1)).
// The twicing kernel 2 vMF(kappa) - vMF(kappa / 2): its normalisations once per kappa, then one
// exponential per cosine.
class TwicedKernel {
public:
    explicit TwicedKernel(double kappa)
        : half_kappa_(kappa / 2),
          narrow_(2 * kappa / (2 * kPi * -std::expm1(-2 * kappa))),
          wide_(kappa / 2 / (2 * kPi * -std::expm1(-kappa))) {}
    double operator()(double t) const {
        const double half = std::exp(half_kappa_ * (t - 1));
        return narrow_ * half * half - wide_ * half;
    }

private:
    double half_kappa_, narrow_, wide_;
};

}  // namespace

DirectionHistogram::DirectionHistogram(const DirectionResolution& resolution)
    : resolution_(resolution), levels_(size_t(resolution.levels)) {
    for (int l = 0; l < resolution.levels; ++l) {
        Level& level = levels_[size_t(l)];
        level.step_deg = resolution.finest_step_deg * double(1 << l);
        // Whole bins on the sphere, so that 2 x 2 of them make one of the next level.
        if (std::fmod(180, level.step_deg) != 0)
            throw std::invalid_argument("direction histogram: bins of " +
                                        std::to_string(level.step_deg) +
                                        " degrees do not divide 180");
        level.rows = size_t(std::lround(180 / level.step_deg));
        level.columns = size_t(std::lround(360 / level.step_deg));
    }
    levels_[0].bins.resize(levels_[0].rows * levels_[0].columns);
}

void DirectionHistogram::add(double x, double y, double polar, double flux) {
    const double gamma = std::atan2(std::hypot(x, y), polar) / kRadiansPerDegree;
    double c = std::atan2(y, x) / kRadiansPerDegree;
    if (c < 0) c += 360;
    Level& level = levels_[0];
    const size_t row = std::min(size_t(gamma / level.step_deg), level.rows - 1);
    const size_t column = std::min(size_t(c / level.step_deg), level.columns - 1);
    Bin& bin = level.bins[row * level.columns + column];
    bin.flux += flux;
    bin.square += flux * flux;
    bin.direction[0] += flux * x;
    bin.direction[1] += flux * y;
    bin.direction[2] += flux * polar;
    total_flux_ += flux;
    total_square_ += flux * flux;
    rays_ += 1;
}

void DirectionHistogram::merge(const DirectionHistogram& other) {
    const Level& from = other.levels_[0];
    Level& to = levels_[0];
    if (from.step_deg != to.step_deg)
        throw std::invalid_argument("direction histogram: merging bins of different sizes");
    for (size_t b = 0; b < to.bins.size(); ++b) {
        to.bins[b].flux += from.bins[b].flux;
        to.bins[b].square += from.bins[b].square;
        for (size_t k = 0; k < 3; ++k) to.bins[b].direction[k] += from.bins[b].direction[k];
    }
    total_flux_ += other.total_flux_;
    total_square_ += other.total_square_;
    rays_ += other.rays_;
}

void DirectionHistogram::prepare() {
    for (size_t l = 1; l < levels_.size(); ++l) {
        const Level& finer = levels_[l - 1];
        Level& level = levels_[l];
        level.bins.assign(level.rows * level.columns, Bin{});
        for (size_t row = 0; row < finer.rows; ++row)
            for (size_t column = 0; column < finer.columns; ++column) {
                const Bin& from = finer.bins[row * finer.columns + column];
                Bin& to = level.bins[row / 2 * level.columns + column / 2];
                to.flux += from.flux;
                to.square += from.square;
                for (int k = 0; k < 3; ++k) to.direction[size_t(k)] += from.direction[size_t(k)];
            }
    }
    for (Level& level : levels_) {
        level.mean.assign(level.bins.size(), {0, 0, 0});
        for (size_t b = 0; b < level.bins.size(); ++b) {
            const auto& d = level.bins[b].direction;
            const double norm = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
            if (norm > 0) level.mean[b] = {d[0] / norm, d[1] / norm, d[2] / norm};
        }
    }
}

const DirectionHistogram::Level& DirectionHistogram::level_for(double sigma_deg) const {
    size_t l = 0;
    while (l + 1 < levels_.size() &&
           levels_[l + 1].step_deg <= sigma_deg / resolution_.bins_per_sigma)
        ++l;
    return levels_[l];
}

template <class Visit>
void DirectionHistogram::visit_bins(const Level& level, double x, double y, double polar,
                                    double radius, Visit&& visit) const {
    const double cos_radius = std::cos(radius);
    const double gamma_u = std::atan2(std::hypot(x, y), polar);
    const double cos_u = std::cos(gamma_u), sin_u = std::sin(gamma_u);
    double c_u = std::atan2(y, x);
    if (c_u < 0) c_u += 2 * kPi;
    const double step = level.step_deg * kRadiansPerDegree;
    const bool whole_circles = gamma_u - radius <= 0 || gamma_u + radius >= kPi;

    // The widest C half-angle of the cap at polar angle g: points (g, c) within `radius` of u
    // have cos(c - c_u) >= (cos R - cos g cos g_u) / (sin g sin g_u). Returns pi for all of C.
    auto half_angle = [&](double g) {
        const double ratio = (cos_radius - std::cos(g) * cos_u) / (std::sin(g) * sin_u);
        if (!(ratio > -1)) return kPi;
        return ratio >= 1 ? 0.0 : std::acos(ratio);
    };

    const size_t first_row = size_t(std::max(0.0, std::floor((gamma_u - radius) / step)));
    const size_t last_row =
        std::min(level.rows - 1, size_t(std::max(0.0, std::floor((gamma_u + radius) / step))));
    for (size_t row = first_row; row <= last_row; ++row) {
        size_t first_column = 0, count = level.columns;
        if (!whole_circles) {
            const double low = double(row) * step, high = low + step;
            const double nearest = std::clamp(gamma_u, low, high);
            const double width =
                std::max({half_angle(std::max(low, 1e-9)), half_angle(std::min(high, kPi - 1e-9)),
                          half_angle(std::clamp(nearest, 1e-9, kPi - 1e-9))});
            const double span = (width + step) * 2 / step + 1;  // columns, one of margin a side
            if (span < double(level.columns)) {
                const double start = std::floor((c_u - width) / step) - 1;
                first_column =
                    size_t(std::fmod(start + double(level.columns) * 2, double(level.columns)));
                count = size_t(span) + 1;
            }
        }
        for (size_t k = 0; k < count; ++k) {
            const size_t b = row * level.columns + (first_column + k) % level.columns;
            const Bin& bin = level.bins[b];
            if (bin.flux == 0) continue;
            const auto& m = level.mean[b];
            const double t = x * m[0] + y * m[1] + polar * m[2];
            if (t >= cos_radius) visit(bin, m, t);
        }
    }
}

DirectionHistogram::Estimate DirectionHistogram::at(double x, double y, double polar,
                                                    double sigma_deg) const {
    const double sigma = sigma_deg * kRadiansPerDegree;
    const TwicedKernel twiced(1 / (sigma * sigma));
    double sum = 0, square = 0;
    visit_bins(level_for(sigma_deg), x, y, polar, std::min(kCutoffSigmas * sigma, kPi),
               [&](const Bin& bin, const std::array<double, 3>&, double t) {
                   const double kernel = twiced(t);
                   sum += bin.flux * kernel;
                   square += bin.square * kernel * kernel;
               });
    const double mean_flux = rays_ > 0 ? total_flux_ / rays_ : 0;
    const double peak = twiced(1) * mean_flux;
    return {sum, std::sqrt(square + peak * peak), sigma_deg};
}

DirectionHistogram::Estimate DirectionHistogram::local_fit(double x, double y, double polar,
                                                           double sigma_deg) const {
    const double sigma = sigma_deg * kRadiansPerDegree, s2 = sigma * sigma;
    // Coordinates of the tangent plane at u: the azimuthal equidistant map (angle from u along
    // the great circle), on an orthonormal basis e1, e2 of the plane.
    Vec3 e1, e2;
    orthonormal_basis({x, y, polar}, e1, e2);
    // Gaussian-weighted flux, first and second moments of the coordinates; the noise through
    // the fit's equivalent kernel at a flat intensity, G (2 - r^2 / (2 sigma^2)).
    double s0 = 0, s1[2] = {0, 0}, s2m[3] = {0, 0, 0}, square = 0;
    visit_bins(level_for(sigma_deg), x, y, polar, std::min(kLocalCutoffSigmas * sigma, kPi),
               [&](const Bin& bin, const std::array<double, 3>& m, double t) {
                   const double theta = std::acos(std::min(1.0, t)), r2 = theta * theta;
                   const Vec3 mean{m[0], m[1], m[2]};
                   const double p1 = dot(mean, e1), p2 = dot(mean, e2);
                   const double norm = std::hypot(p1, p2);
                   const double a = norm > 0 ? theta * p1 / norm : 0;
                   const double b = norm > 0 ? theta * p2 / norm : 0;
                   const double weight = std::exp(-r2 / (2 * s2)), w = bin.flux * weight;
                   s0 += w;
                   s1[0] += w * a, s1[1] += w * b;
                   s2m[0] += w * a * a, s2m[1] += w * a * b, s2m[2] += w * b * b;
                   const double equivalent = weight * (2 - r2 / (2 * s2)) / (2 * kPi * s2);
                   square += bin.square * equivalent * equivalent;
               });
    const double mean_flux = rays_ > 0 ? total_flux_ / rays_ : 0;
    const double peak = 2 / (2 * kPi * s2) * mean_flux;
    Estimate e{0, std::sqrt(square + peak * peak), sigma_deg, Kind::log_quadratic};
    if (!(s0 > 0)) return e;
    // The intensity exp(a + g.t - t.H.t / 2) times the weight is a Gaussian of the moments'
    // mean m and covariance V: I(u) = exp(a) = s0 / (2 pi sqrt(det V)) exp(-m.V^-1.m / 2).
    const double m1 = s1[0] / s0, m2 = s1[1] / s0;
    const double v11 = s2m[0] / s0 - m1 * m1, v12 = s2m[1] / s0 - m1 * m2;
    const double v22 = s2m[2] / s0 - m2 * m2;
    const double det = v11 * v22 - v12 * v12;
    if (!(det > kMinCovarianceRatio * s2 * s2)) {
        e.intensity = s0 / (2 * kPi * s2);  // too few bins to fit a shape: the Gaussian kernel's
        return e;
    }
    const double q = (v22 * m1 * m1 - 2 * v12 * m1 * m2 + v11 * m2 * m2) / det;
    e.intensity = s0 / (2 * kPi * std::sqrt(det)) * std::exp(-0.5 * q);
    return e;
}

namespace {

// The edge fit's model along its gradient: (a + b s)_+ under Gaussian weights of width sigma.
// With z = a / (b sigma), its weighted flux is M0 = b sigma (z Phi(z) + phi(z)) and its first
// moment M1 = b sigma^2 Phi(z), so that M1 / (sigma M0) = F(z) = Phi / (z Phi + phi) falls from
// infinity (the edge far on the near side: no intensity here) to 0 (no edge within reach), and
// the intensity here is a = M0 G(z) with G = z / (z Phi + phi).
struct EdgeSolution {
    double z, ratio, slope, gain, gain_slope;  // z, F(z), F'(z), G(z), G'(z)
    double spread;  // M2 / (sigma^2 M0) = (z Phi + 2 phi) / (z Phi + phi)
};
double normal_density(double z) { return std::exp(-z * z / 2) / std::sqrt(2 * kPi); }
double normal_probability(double z) { return std::erfc(-z / std::sqrt(2.0)) / 2; }
EdgeSolution edge_at(double z) {
    const double phi = normal_density(z), cdf = normal_probability(z), d = z * cdf + phi;
    return {z, cdf / d, (phi * d - cdf * cdf) / (d * d), z / d, phi / (d * d), (d + phi) / d};
}
// Beyond these, the edge lies farther than the weights reach (kEdgeFar sigmas on the far side:
// a linear fit), or the direction lies kEdgeNear sigmas outside it (no intensity).
constexpr double kEdgeFar = 30, kEdgeNear = -6;
// How many standard errors the second moments may lie from the edge model's (1: best of 1 and 2
// on the analytic sources of tests/bench/farfield_accuracy).
constexpr double kEdgeSpreadTolerance = 1;
// F(z) = ratio by bisection (F falls monotonically), for F(kEdgeFar) < ratio < F(kEdgeNear).
EdgeSolution solve_edge(double ratio) {
    double low = kEdgeNear, high = kEdgeFar;
    for (int i = 0; i < 60; ++i) {
        const double mid = (low + high) / 2;
        (edge_at(mid).ratio > ratio ? low : high) = mid;
    }
    return edge_at((low + high) / 2);
}

}  // namespace

DirectionHistogram::Estimate DirectionHistogram::edge_fit(double x, double y, double polar,
                                                          double sigma_deg) const {
    bool edge_like;
    return edge_fit(x, y, polar, sigma_deg, edge_like);
}

DirectionHistogram::Estimate DirectionHistogram::edge_fit(double x, double y, double polar,
                                                          double sigma_deg, bool& edge_like) const {
    // The intensity of a flat Lambertian emitter is I(v) = max(0, c.v). In the gnomonic
    // projection about u, p = v / (u.v) - u, it is (u.v) (a + b.p)_+ with a = c.u the intensity
    // here, and the solid angle is dOmega = (u.v)^3 dp: so the rays weighted by w(p) / (u.v)^4
    // measure the moments of the plane function (a + b.p)_+ under the Gaussian weight w, exactly.
    const double sigma = sigma_deg * kRadiansPerDegree, s2 = sigma * sigma;
    Vec3 e1, e2;
    orthonormal_basis({x, y, polar}, e1, e2);
    // Weighted flux m0, first and second moments m1, m2 of p; for the noise, the same moments of
    // the squared fluxes with the squared weights.
    double m0 = 0, m1[2] = {0, 0}, m2[3] = {0, 0, 0}, q0 = 0, q1[2] = {0, 0}, q2[3] = {0, 0, 0};
    visit_bins(level_for(sigma_deg), x, y, polar, std::atan(kLocalCutoffSigmas * sigma),
               [&](const Bin& bin, const std::array<double, 3>& m, double t) {
                   const Vec3 mean{m[0], m[1], m[2]};
                   const double p1 = dot(mean, e1) / t, p2 = dot(mean, e2) / t;
                   const double k = std::exp(-(p1 * p1 + p2 * p2) / (2 * s2)) / (t * t * t * t);
                   const double f = bin.flux * k, g = bin.square * k * k;
                   m0 += f, m1[0] += f * p1, m1[1] += f * p2;
                   m2[0] += f * p1 * p1, m2[1] += f * p1 * p2, m2[2] += f * p2 * p2;
                   q0 += g, q1[0] += g * p1, q1[1] += g * p2;
                   q2[0] += g * p1 * p1, q2[1] += g * p1 * p2, q2[2] += g * p2 * p2;
               });
    const double norm = 1 / (2 * kPi * s2);
    const double mean_flux = rays_ > 0 ? total_flux_ / rays_ : 0;
    Estimate e{0, norm * mean_flux, sigma_deg, Kind::edge};
    edge_like = false;
    if (!(m0 > 0)) return e;
    const double gradient = std::hypot(m1[0], m1[1]), ratio = gradient / (sigma * m0);
    // The bounds of the ratio, computed once.
    static const double near_ratio = edge_at(kEdgeNear).ratio, far_ratio = edge_at(kEdgeFar).ratio;
    if (ratio >= near_ratio) return e;  // beyond the edge: no intensity
    const double u1 = gradient > 0 ? m1[0] / gradient : 1, u2 = gradient > 0 ? m1[1] / gradient : 0;
    // a = M0 G(z); each ray of weight k at p adds flux k (A + B s) to it, s = p along the
    // gradient: the fit's equivalent kernel, which carries the rays' noise.
    double a = m0, A = 1, B = 0, spread = 1;
    if (ratio > far_ratio) {
        const EdgeSolution edge = solve_edge(ratio);
        a = m0 * edge.gain;
        A = edge.gain - edge.gain_slope * edge.ratio / edge.slope;
        B = edge.gain_slope / (sigma * edge.slope);
        spread = edge.spread;
    }
    // The model holds where the rays spread along the gradient as an edge does and across it
    // as a flat intensity does, within the noise of second moments (relative sqrt(2 / n) for
    // n effective rays): elsewhere (a curved lobe) the fit is biased as a Gaussian kernel is.
    const double along = (m2[0] * u1 * u1 + 2 * m2[1] * u1 * u2 + m2[2] * u2 * u2) / (m0 * s2);
    const double across = (m2[0] + m2[2]) / (m0 * s2) - along;
    const double tolerance = kEdgeSpreadTolerance * std::sqrt(2 * q0 / (m0 * m0));
    edge_like = std::abs(along - spread) <= tolerance * along && std::abs(across - 1) <= tolerance;
    const double q1u = q1[0] * u1 + q1[1] * u2;
    const double q2u = q2[0] * u1 * u1 + 2 * q2[1] * u1 * u2 + q2[2] * u2 * u2;
    const double variance = A * A * (q0 + mean_flux * mean_flux) + 2 * A * B * q1u + B * B * q2u;
    e.intensity = norm * std::max(0.0, a);
    e.standard_error = norm * std::sqrt(std::max(0.0, variance));
    return e;
}

DirectionHistogram::Estimate DirectionHistogram::at_kernel_of(double x, double y, double polar,
                                                              const Estimate& chosen) const {
    switch (chosen.kind) {
        case Kind::log_quadratic: return local_fit(x, y, polar, chosen.sigma_deg);
        case Kind::edge: return edge_fit(x, y, polar, chosen.sigma_deg);
        case Kind::kernel: break;
    }
    return at(x, y, polar, chosen.sigma_deg);
}

namespace {

// The overlaps of the estimates' equivalent kernels, in the plane (locally, the sphere), as sums
// of Gaussians G_s and local-fit kernels L_s = G_s - (s / 2) dG_s / ds: the twiced kernel is
// 2 G_s - G_(sqrt2 s), the log-quadratic fit L_s, the edge fit away from its edge G_s.
struct KernelPart {
    double weight, sigma;
    bool local;
};
double part_overlap(const KernelPart& p, const KernelPart& q) {
    const double a = p.sigma, b = q.sigma, s = a * a + b * b;
    if (!p.local && !q.local) return 1 / (2 * kPi * s);
    if (p.local && q.local) return (2 / s + 2 * a * a * b * b / (s * s * s)) / (2 * kPi);
    const double l = p.local ? a : b;  // the local-fit kernel's width against the Gaussian
    return (1 / s + l * l / (s * s)) / (2 * kPi);
}
std::vector<KernelPart> kernel_parts(const DirectionHistogram::Estimate& e) {
    using Kind = DirectionHistogram::Kind;
    switch (e.kind) {
        case Kind::log_quadratic: return {{1, e.sigma_deg, true}};
        case Kind::edge: return {{1, e.sigma_deg, false}};
        case Kind::kernel: break;
    }
    return {{2, e.sigma_deg, false}, {-1, std::sqrt(2.0) * e.sigma_deg, false}};
}
double overlap(const DirectionHistogram::Estimate& s, const DirectionHistogram::Estimate& r) {
    double sum = 0;
    for (const KernelPart& p : kernel_parts(s))
        for (const KernelPart& q : kernel_parts(r)) sum += p.weight * q.weight * part_overlap(p, q);
    return sum;
}

// The standard error of the difference of two estimates made from the same rays, whose
// correlation is that of their kernels over a locally uniform density.
double difference_error(const DirectionHistogram::Estimate& s,
                        const DirectionHistogram::Estimate& r) {
    const double rho = overlap(s, r) / std::sqrt(overlap(s, s) * overlap(r, r));
    const double v = s.standard_error * s.standard_error + r.standard_error * r.standard_error -
                     2 * rho * s.standard_error * r.standard_error;
    return std::sqrt(std::max(0.0, v));
}

}  // namespace

DirectionHistogram::Estimate DirectionHistogram::adaptive(double x, double y, double polar) const {
    // The ladder of bandwidths, each sqrt(2) times the one below: the estimates and their rungs.
    std::vector<Estimate> ladder;
    std::vector<int> rung;
    int r = 0;
    for (double sigma = resolution_.min_sigma_deg; sigma <= resolution_.max_sigma_deg * 1.0001;
         sigma *= std::sqrt(2.0), ++r) {
        ladder.push_back(at(x, y, polar, sigma));
        if (resolution_.local_fits) {
            ladder.push_back(local_fit(x, y, polar, sigma));
            bool edge_like;
            const Estimate edge = edge_fit(x, y, polar, sigma, edge_like);
            if (edge_like) ladder.push_back(edge);
        }
        rung.resize(ladder.size(), r);
    }
    // The bias of an estimate bounded by how far it lies from those of the same or smaller
    // bandwidths beyond the noise of their difference; the estimate with the least bound plus
    // noise. A log-quadratic fit is not held to kernels wider than half its width (two rungs
    // down): they flatten a lobe the fit follows (their bias grows as sigma^4: 1/16 of it at half
    // the width).
    size_t best = 0;
    double best_score = HUGE_VAL;
    for (size_t s = 0; s < ladder.size(); ++s) {
        const bool lobe_fit = ladder[s].kind == Kind::log_quadratic;
        double bias = 0;
        for (size_t t = 0; t < ladder.size(); ++t) {
            const int reach = lobe_fit && ladder[t].kind == Kind::kernel ? rung[s] - 2 : rung[s];
            if (t != s && rung[t] <= reach)
                bias = std::max(bias, std::abs(ladder[s].intensity - ladder[t].intensity) -
                                          kMargin * difference_error(ladder[s], ladder[t]));
        }
        const double score = bias + kMargin * ladder[s].standard_error;
        if (score < best_score) best_score = score, best = s;
    }
    return ladder[best];
}

}  // namespace rayset
