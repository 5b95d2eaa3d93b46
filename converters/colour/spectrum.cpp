#include "converters/colour/spectrum.h"

#include "converters/colour/cie_tables.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rayset {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Integral over [a, b] of the product of two functions that are linear on [a, b], given their
// values at a, the midpoint and b: Simpson's rule is exact for the quadratic product.
double product_integral(double a, double b, double fa, double fm, double fb, double ga, double gm,
                        double gb) {
    return (b - a) * (fa * ga + 4 * fm * gm + fb * gb) / 6;
}

}  // namespace

double photopic_efficiency(double wavelength_nm) {
    if (std::isnan(wavelength_nm)) return kNaN;
    if (wavelength_nm < kCiePhotopicFirst || wavelength_nm > kCiePhotopicLast) return 0;
    const double x = wavelength_nm - kCiePhotopicFirst;
    const int i = std::min(static_cast<int>(x), kCiePhotopicCount - 2);
    const double f = x - i;
    return kCiePhotopic[i] * (1 - f) + kCiePhotopic[i + 1] * f;
}

// The table is read as a piecewise-linear spectrum, like V itself. Integrating the product of
// the two exactly (on the union of both grids) matters: the trapezoid rule on the table's own
// points alone misses the curvature of V and is 3e-4 low on the 1.6 nm OSRAM table.
double luminous_efficacy(const SpectralTable& table) {
    const auto& w = table.wavelength;
    const auto& s = table.weight;
    const size_t n = std::min(w.size(), s.size());
    if (n == 0) return kNaN;
    if (n == 1)
        return s[0] > 0 ? kMaxLuminousEfficacy * photopic_efficiency(w[0])
                        : kNaN;  // a spectral line

    double power = 0, luminous = 0;
    for (size_t i = 0; i + 1 < n; ++i) {
        const double a = w[i], b = w[i + 1];
        if (!(b >= a)) return kNaN;  // not ascending: no spectrum
        const double sa = s[i], sb = s[i + 1];
        power += (b - a) * (sa + sb) / 2;
        auto weight_at = [&](double x) { return b > a ? sa + (sb - sa) * (x - a) / (b - a) : sa; };
        // Split [a, b] at V's 1 nm knots so both factors are linear on every piece.
        double lo = a;
        while (lo < b) {
            double hi = std::min(b, std::floor(lo) + 1);
            const double mid = (lo + hi) / 2;
            luminous += product_integral(lo, hi, weight_at(lo), weight_at(mid), weight_at(hi),
                                         photopic_efficiency(lo), photopic_efficiency(mid),
                                         photopic_efficiency(hi));
            lo = hi;
        }
    }
    return power > 0 ? kMaxLuminousEfficacy * luminous / power : kNaN;
}

PhotometricWeights::PhotometricWeights(const RayHeader& header) : header_(&header) {
    table_efficacy_.reserve(header.spectral_tables.size());
    for (const SpectralTable& t : header.spectral_tables)
        table_efficacy_.push_back(luminous_efficacy(t));
    single_efficacy_ = kMaxLuminousEfficacy * photopic_efficiency(header.single_wavelength);
    const bool spectral = header.spectral != SpectralKind::none;
    luminous_known_ = header.has_luminous || (header.has_radiant && spectral);
    radiant_known_ = header.has_radiant || (header.has_luminous && spectral);
}

double PhotometricWeights::efficacy(const Ray& ray) const {
    switch (header_->spectral) {
        case SpectralKind::none: return kNaN;
        case SpectralKind::single_wavelength: return single_efficacy_;
        case SpectralKind::per_ray_wavelength:
            return kMaxLuminousEfficacy * photopic_efficiency(ray.wavelength);
        case SpectralKind::shared_table: return table_efficacy_.empty() ? kNaN : table_efficacy_[0];
        case SpectralKind::per_ray_table:
            return ray.spectrum >= 0 && size_t(ray.spectrum) < table_efficacy_.size()
                       ? table_efficacy_[ray.spectrum]
                       : kNaN;
    }
    return kNaN;
}

std::optional<double> PhotometricWeights::shared_efficacy() const {
    const SpectralKind kind = header_->spectral;
    if (kind != SpectralKind::single_wavelength && kind != SpectralKind::shared_table)
        return std::nullopt;
    return efficacy(Ray{});
}

double PhotometricWeights::luminous(const Ray& ray) const {
    if (header_->has_luminous) return ray.luminous;
    if (header_->has_radiant) return ray.radiant * efficacy(ray);
    return kNaN;
}

double PhotometricWeights::radiant(const Ray& ray) const {
    if (header_->has_radiant) return ray.radiant;
    if (!header_->has_luminous) return kNaN;
    // Light outside the visible band has efficacy 0: its luminous flux says nothing of its power.
    const double e = efficacy(ray);
    return e > 0 ? ray.luminous / e : kNaN;
}

}  // namespace rayset
