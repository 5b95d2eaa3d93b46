// Accumulators of the progressive render: the image (one RGB radiance sample per pixel per
// pass) and the illuminance receivers (one irradiance sample per cell per pass). Both hold
// SI values: radiance in W/(m^2 sr) and irradiance in W/m^2 per linear-sRGB channel, with the
// photometric value (cd/m^2, lx) and its standard error derived from them.
#pragma once

#include <string>
#include <vector>

#include "tracer/render/rgb.h"

namespace rayset::tracer {

// Per-cell sums of samples: the mean and the standard error of the mean's photometric value.
class SampleGrid {
public:
    SampleGrid(int nx, int ny)
        : nx_(nx), ny_(ny), sum_(size_t(nx) * ny), photometric_squares_(size_t(nx) * ny) {}
    // A grid continuing from stored sums (checkpoint.h): adding to it gives the very bits an
    // uninterrupted grid would hold. Throws rayset::Error when the sizes disagree.
    static SampleGrid restored(int nx, int ny, int samples, std::vector<Rgb> sums,
                               std::vector<double> photometric_squares);
    int nx() const { return nx_; }
    int ny() const { return ny_; }
    int samples() const { return samples_; }
    void add(int x, int y, Rgb value) {
        const size_t i = size_t(y) * nx_ + x;
        sum_[i] += value;
        const double p = photometric(value);
        photometric_squares_[i] += p * p;
    }
    void finish_pass() { ++samples_; }
    Rgb mean(int x, int y) const;
    double photometric_mean(int x, int y) const { return photometric(mean(x, y)); }
    // Standard error of photometric_mean from the spread of the samples (0 with one sample).
    double photometric_standard_error(int x, int y) const;
    // The accumulators as numbers (samples, sums, squares) appended to `out`, and another such
    // grid's numbers, read from `in` (advanced past them), added to these: how processes
    // that rendered different passes of one render combine them.
    void append_accumulators(std::vector<double>& out) const;
    void add_accumulators(const double*& in);
    // The accumulators themselves, row by row: what a checkpoint stores.
    const std::vector<Rgb>& sums() const { return sum_; }
    const std::vector<double>& photometric_squares() const { return photometric_squares_; }

private:
    int nx_, ny_;
    int samples_ = 0;
    std::vector<Rgb> sum_;
    std::vector<double> photometric_squares_;
};

// Image: pixel (x, y), y downward as in the file.
using Film = SampleGrid;

struct ReceiverMap {
    IlluminanceReceiver receiver;  // name, corner, edges (scene units), resolution
    SampleGrid irradiance;         // W/m^2 per channel; photometric value in lux
    explicit ReceiverMap(const IlluminanceReceiver& r) : receiver(r), irradiance(r.nx, r.ny) {}
    Vec3 cell_centre(int i, int j) const {
        return receiver.corner + ((i + 0.5) / receiver.nx) * receiver.edge1 +
               ((j + 0.5) / receiver.ny) * receiver.edge2;
    }
    // Unit normal of the side the receiver records light from: cross(edge1, edge2).
    Vec3 front_normal() const { return normalized(cross(receiver.edge1, receiver.edge2)); }
};

}  // namespace rayset::tracer
