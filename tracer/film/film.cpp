// Means and standard errors of the sample grids.
#include "tracer/film/film.h"

#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "core/error.h"

namespace rayset::tracer {

SampleGrid SampleGrid::restored(int nx, int ny, int samples, std::vector<Rgb> sums,
                                std::vector<double> photometric_squares) {
    const size_t cells = size_t(nx) * ny;
    if (nx < 1 || ny < 1 || samples < 0 || sums.size() != cells ||
        photometric_squares.size() != cells)
        throw Error(fmt::format("sample grid of {} x {} cells with {} sums and {} squares", nx, ny,
                                sums.size(), photometric_squares.size()));
    SampleGrid grid(nx, ny);
    grid.samples_ = samples;
    grid.sum_ = std::move(sums);
    grid.photometric_squares_ = std::move(photometric_squares);
    return grid;
}

void SampleGrid::append_accumulators(std::vector<double>& out) const {
    out.push_back(samples_);
    for (const Rgb& s : sum_) out.insert(out.end(), {s.red, s.green, s.blue});
    out.insert(out.end(), photometric_squares_.begin(), photometric_squares_.end());
}

void SampleGrid::add_accumulators(const double*& in) {
    samples_ += int(*in++);
    for (Rgb& s : sum_) s += Rgb{in[0], in[1], in[2]}, in += 3;
    for (double& square : photometric_squares_) square += *in++;
}

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
