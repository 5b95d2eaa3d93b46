// Means and standard errors of the sample grids.
#include "tracer/film/film.h"

#include <cmath>

namespace rayset::tracer {

Rgb SampleGrid::mean(int x, int y) const {
    return samples_ ? (1.0 / samples_) * sum_[size_t(y) * nx_ + x] : Rgb{};
}

double SampleGrid::photometric_standard_error(int x, int y) const {
    if (samples_ < 2) return 0;
    const size_t i = size_t(y) * nx_ + x;
    const double n = samples_, mean = photometric(sum_[i]) / n;
    const double variance = std::max(0.0, (photometric_squares_[i] - n * mean * mean) / (n - 1));
    return std::sqrt(variance / n);
}

}  // namespace rayset::tracer
