// Bounds and quantiles the statistical tests share: a binomial count's Bernstein bound and
// the chi-square critical value.
#pragma once

#include <cmath>

namespace rayset::test {

// Half-width t with P(|X - n p| >= t) <= alpha for X ~ Binomial(n, p), from Bernstein's
// inequality (valid at every count, unlike the normal approximation):
// P(|X - np| >= t) <= 2 exp(-t^2 / (2 (n p (1-p) + t/3))).
inline double bernstein_bound(double n, double p, double alpha) {
    const double l = std::log(2 / alpha), variance = n * p * (1 - p);
    return l / 3 + std::sqrt(l * l / 9 + 2 * l * variance);
}

// Upper 1 - alpha quantile of chi-square with k degrees of freedom, Wilson-Hilferty (1931):
// k (1 - 2/(9k) + z sqrt(2/(9k)))^3, z the normal quantile (relative error < 1e-3 for k > 100).
inline double chi_square_critical(double k, double z) {
    const double c = 2 / (9 * k);
    return k * std::pow(1 - c + z * std::sqrt(c), 3);
}

}  // namespace rayset::test
