// Building, querying, sampling and storing a goniometric diagram (goniometric_diagram.h).
#include "lightmodel/goniometric_diagram.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace rayset::lightmodel {

namespace {

constexpr double kOneMinusEpsilon = 0x1.fffffffffffffp-1;
constexpr int kMaxGridSize = 4096;  // bands and sectors; bounds what deserialize() accepts

// Inverts the CDF of the density on [0,1] that is linear from a (at 0) to b (at 1), a, b >= 0.
// The form u (a + b) / (a + sqrt(lerp(u, a^2, b^2))) avoids the cancellation of the textbook
// quadratic root when a and b are close.
double sample_linear(double u, double a, double b) {
    const double denominator = a + std::sqrt((1 - u) * a * a + u * b * b);
    if (denominator == 0) return u;  // a = b = 0: a zero-probability line, any point will do
    return std::min(u * (a + b) / denominator, kOneMinusEpsilon);
}

// Azimuth of `w` in [0, 2 pi].
double azimuth(Vec3 w) {
    const double phi = std::atan2(w.y, w.x);
    return phi < 0 ? phi + 2 * kPi : phi;
}

// Value at a grid line of the density known at the two nearest centres on one side of it, at
// distances h/2 (`near`) and 3h/2 (`far`): linear extrapolation, clamped so the density stays
// >= 0. Without a second centre, the nearest one's value.
double extrapolate(double near, double far, bool has_far) {
    return has_far ? std::max(0.0, 1.5 * near - 0.5 * far) : near;
}

// u of node row `row` of a diagram of `bands` bands (see row_count()).
double u_of_row(int row, int bands) {
    const int half = bands / 2;
    if (row == 0) return -1;
    if (row == bands + 3) return 1;
    if (row == half + 1 || row == half + 2) return 0;
    const int band = row <= half ? row - 1 : row - 3;
    return -1 + (band + 0.5) * 2 / bands;
}

}  // namespace

GoniometricDiagram::GoniometricDiagram(int bands, int sectors) : bands_(bands), sectors_(sectors) {
    if (bands < 2 || bands % 2 != 0 || bands > kMaxGridSize)
        throw std::invalid_argument("goniometric diagram bands must be even, in [2, 4096]");
    if (sectors < 1 || sectors > kMaxGridSize)
        throw std::invalid_argument("goniometric diagram sectors must be in [1, 4096]");
    histogram_.assign(size_t(cell_count()), 0.0);
    for (int row = 0; row < row_count(); ++row) row_u_.push_back(u_of_row(row, bands_));
}

double GoniometricDiagram::cell_solid_angle() const { return 4 * kPi / cell_count(); }

int GoniometricDiagram::band_of(double u) const {
    // The hemisphere is decided by the sign of u itself, so that no rounding of u + 1 can put
    // a direction on the other side of the horizon from the one pdf() and sample() see.
    const int half = bands_ / 2;
    const int band = int(std::floor((u + 1) * half));
    return u >= 0 ? std::clamp(band, half, bands_ - 1) : std::clamp(band, 0, half - 1);
}

int GoniometricDiagram::sector_of(double phi) const {
    return std::clamp(int(phi * sectors_ / (2 * kPi)), 0, sectors_ - 1);
}

int GoniometricDiagram::cell_of(Vec3 w) const {
    return band_of(std::clamp(w.z, -1.0, 1.0)) * sectors_ + sector_of(azimuth(w));
}

void GoniometricDiagram::accumulate(Vec3 w, double weight) {
    if (!has_histogram())
        throw std::logic_error("a deserialised goniometric diagram cannot accumulate");
    if (!(weight >= 0) || !std::isfinite(weight))
        throw std::invalid_argument("goniometric diagram weight must be finite and >= 0");
    histogram_[size_t(cell_of(w))] += weight;
    total_weight_ += weight;
    finalized_ = false;
}

void GoniometricDiagram::merge(const GoniometricDiagram& other) {
    if (other.bands_ != bands_ || other.sectors_ != sectors_)
        throw std::invalid_argument("merging goniometric diagrams of different grids");
    if (!has_histogram() || !other.has_histogram())
        throw std::logic_error("a deserialised goniometric diagram cannot be merged");
    for (size_t c = 0; c < histogram_.size(); ++c) histogram_[c] += other.histogram_[c];
    total_weight_ += other.total_weight_;
    finalized_ = false;
}

void GoniometricDiagram::finalize() {
    if (!has_histogram())
        throw std::logic_error("a deserialised goniometric diagram is already final");
    std::vector<double> centres(histogram_.size(), 0.0);
    if (total_weight_ > 0) {
        const double per_weight = 1 / (total_weight_ * cell_solid_angle());
        for (size_t c = 0; c < centres.size(); ++c) centres[c] = histogram_[c] * per_weight;
    }
    build_nodes(centres);
    normalise_nodes();
    finalized_ = true;
}

void GoniometricDiagram::build_nodes(const std::vector<double>& centres) {
    const int half = bands_ / 2;
    const bool two_per_side = half >= 2;
    nodes_.assign(size_t(row_count()) * sectors_, 0.0f);
    for (int band = 0; band < bands_; ++band)
        for (int j = 0; j < sectors_; ++j)
            stored_node(centre_row(band), j) = float(centres[size_t(band) * sectors_ + j]);

    auto ring_mean = [&](int band) {
        double sum = 0;
        for (int j = 0; j < sectors_; ++j) sum += node(centre_row(band), j);
        return sum / sectors_;
    };
    const double south = extrapolate(ring_mean(0), two_per_side ? ring_mean(1) : 0, two_per_side);
    const double north =
        extrapolate(ring_mean(bands_ - 1), two_per_side ? ring_mean(bands_ - 2) : 0, two_per_side);
    for (int j = 0; j < sectors_; ++j) {
        stored_node(0, j) = float(south);
        stored_node(row_count() - 1, j) = float(north);
        auto centre = [&](int band) { return double(node(centre_row(band), j)); };
        const double below = centre(half - 1), above = centre(half);
        if (below > 0 && above > 0) {
            // Light on both sides: the horizon is an ordinary line between two centres.
            stored_node(half + 1, j) = stored_node(half + 2, j) = float(0.5 * (below + above));
        } else {
            // A side without light: each side's own extrapolation, so the cut-off stays sharp
            // (the dark side's is 0).
            stored_node(half + 1, j) =
                float(extrapolate(below, two_per_side ? centre(half - 2) : 0, two_per_side));
            stored_node(half + 2, j) =
                float(extrapolate(above, two_per_side ? centre(half + 1) : 0, two_per_side));
        }
    }
}

void GoniometricDiagram::normalise_nodes() {
    // A bilinear patch integrates to the mean of its corners times its extent in (u, phi),
    // which is its solid angle. The two horizon rows are one line: that patch has no extent.
    const double sector_width = 2 * kPi / sectors_;
    std::vector<double> masses(size_t(row_count() - 1) * sectors_);
    double integral = 0;
    for (int r = 0; r + 1 < row_count(); ++r) {
        const double extent = (row_u(r + 1) - row_u(r)) * sector_width;
        for (int j = 0; j < sectors_; ++j) {
            const int j1 = (j + 1) % sectors_;
            const double mean =
                0.25 * (node(r, j) + node(r, j1) + node(r + 1, j) + node(r + 1, j1));
            masses[size_t(r) * sectors_ + j] = mean * extent;
            integral += mean * extent;
        }
    }
    if (!(integral > 0)) {
        std::fill(nodes_.begin(), nodes_.end(), 0.0f);
        scale_ = 0;
        patches_ = AliasTable();
        return;
    }
    scale_ = 1 / integral;
    patches_ = AliasTable(masses);
}

void GoniometricDiagram::require_finalized() const {
    if (!finalized_) throw std::logic_error("goniometric diagram queried before finalize()");
}

bool GoniometricDiagram::empty() const {
    require_finalized();
    return patches_.empty();
}

double GoniometricDiagram::density(double u, double phi) const {
    const int centre = centre_row(band_of(u));
    const int r = u < row_u(centre) ? centre - 1 : centre;
    const double u0 = row_u(r), u1 = row_u(r + 1);
    const double t = std::clamp((u - u0) / (u1 - u0), 0.0, 1.0);
    // Node columns sit at the sectors' centres (j + 1/2) 2 pi / sectors.
    const double x = phi * sectors_ / (2 * kPi) - 0.5;
    const double column = std::floor(x);
    const double f = std::clamp(x - column, 0.0, 1.0);
    int j0 = int(column);  // -1 to sectors_ - 1 for phi in [0, 2 pi)
    if (j0 < 0 || j0 >= sectors_) j0 = (j0 % sectors_ + sectors_) % sectors_;
    const int j1 = j0 + 1 < sectors_ ? j0 + 1 : 0;
    const double lower = (1 - f) * node(r, j0) + f * node(r, j1);
    const double upper = (1 - f) * node(r + 1, j0) + f * node(r + 1, j1);
    return scale_ * ((1 - t) * lower + t * upper);
}

double GoniometricDiagram::pdf(Vec3 w) const {
    require_finalized();
    return density(std::clamp(w.z, -1.0, 1.0), azimuth(w));
}

double GoniometricDiagram::bin_average(int cell) const {
    require_finalized();
    if (cell < 0 || cell >= cell_count())
        throw std::out_of_range("goniometric diagram cell out of range");
    // The lines through the cell's centre split it into four quarters of equal solid angle,
    // each inside one bilinear patch, whose mean is its value at the quarter's centre.
    const int band = cell / sectors_, sector = cell % sectors_;
    const double u = row_u(centre_row(band)), quarter_u = 0.5 / bands_;
    const double phi = (sector + 0.5) * 2 * kPi / sectors_, quarter_phi = 0.5 * kPi / sectors_;
    return 0.25 *
           (density(u - quarter_u, phi - quarter_phi) + density(u - quarter_u, phi + quarter_phi) +
            density(u + quarter_u, phi - quarter_phi) + density(u + quarter_u, phi + quarter_phi));
}

DirectionSample GoniometricDiagram::sample(Vec2 u) const {
    if (empty()) throw std::logic_error("cannot sample an empty goniometric diagram");
    // A patch drawn by its mass, and the rest of u.x to place the sample within it.
    const AliasTable::Sample drawn = patches_.sample(std::clamp(u.x, 0.0, kOneMinusEpsilon));
    const int patch = drawn.index;
    const double u_in_patch = std::clamp(drawn.u_remapped, 0.0, kOneMinusEpsilon);

    const int r = patch / sectors_, j0 = patch % sectors_, j1 = (j0 + 1) % sectors_;
    const double v00 = node(r, j0), v10 = node(r, j1), v01 = node(r + 1, j0), v11 = node(r + 1, j1);
    // dOmega = du dphi: marginal in phi linear between the column sums, conditional in u linear
    // between the bilinear's values on the patch's two rows at that phi.
    const double f = sample_linear(u_in_patch, v00 + v01, v10 + v11);
    const double lower = (1 - f) * v00 + f * v10, upper = (1 - f) * v01 + f * v11;
    const double t = sample_linear(std::clamp(u.y, 0.0, kOneMinusEpsilon), lower, upper);

    // (1 - t) u0 + t u1 never rounds onto u1 = 0 from below (t < 1), which keeps a sample of
    // the patch under the horizon on the side whose density it was drawn from.
    const double z = (1 - t) * row_u(r) + t * row_u(r + 1);
    double phi = (j0 + 0.5 + f) * 2 * kPi / sectors_;
    if (phi >= 2 * kPi) phi -= 2 * kPi;
    const double s = std::sqrt(std::max(0.0, (1 - z) * (1 + z)));
    DirectionSample sample;
    sample.direction = {s * std::cos(phi), s * std::sin(phi), z};
    sample.pdf = scale_ * ((1 - t) * lower + t * upper);
    return sample;
}

std::vector<float> GoniometricDiagram::serialize() const {
    require_finalized();
    std::vector<float> data;
    data.reserve(3 + size_t(cell_count()));
    data.push_back(float(bands_));
    data.push_back(float(sectors_));
    data.push_back(float(total_weight_));
    for (int band = 0; band < bands_; ++band)
        for (int j = 0; j < sectors_; ++j) data.push_back(float(node(centre_row(band), j)));
    return data;
}

GoniometricDiagram GoniometricDiagram::deserialize(const std::vector<float>& data) {
    auto is_count = [](float v) { return v >= 1 && v <= kMaxGridSize && v == std::floor(v); };
    if (data.size() < 3 || !is_count(data[0]) || !is_count(data[1]) || int(data[0]) % 2 != 0)
        throw std::invalid_argument("goniometric diagram data: bad grid size");
    const int bands = int(data[0]), sectors = int(data[1]);
    const size_t cells = size_t(bands) * sectors;
    if (data.size() != 3 + cells)
        throw std::invalid_argument("goniometric diagram data: expected " +
                                    std::to_string(3 + cells) + " values for a " +
                                    std::to_string(bands) + " x " + std::to_string(sectors) +
                                    " grid, got " + std::to_string(data.size()));
    if (!(data[2] >= 0) || !std::isfinite(data[2]))
        throw std::invalid_argument(
            "goniometric diagram data: total weight must be finite and >= 0");
    return from_densities(bands, sectors, data[2],
                          std::vector<double>(data.begin() + 3, data.end()));
}

GoniometricDiagram GoniometricDiagram::from_densities(int bands, int sectors, double total_weight,
                                                      const std::vector<double>& centres) {
    GoniometricDiagram diagram(bands, sectors);
    if (centres.size() != diagram.histogram_.size())
        throw std::invalid_argument("goniometric diagram: expected " +
                                    std::to_string(diagram.histogram_.size()) +
                                    " cell densities, got " + std::to_string(centres.size()));
    for (double value : centres)
        if (!(value >= 0) || !std::isfinite(value))
            throw std::invalid_argument(
                "goniometric diagram data: densities must be finite and >= 0");
    diagram.histogram_.clear();
    diagram.total_weight_ = total_weight;
    diagram.build_nodes(centres);
    diagram.normalise_nodes();
    diagram.finalized_ = true;
    return diagram;
}

Vec3 GoniometricDiagram::cell_centre(int cell) const {
    const int band = cell / sectors_, sector = cell % sectors_;
    const double z = row_u(centre_row(band)), phi = (sector + 0.5) * 2 * kPi / sectors_;
    const double s = std::sqrt(std::max(0.0, (1 - z) * (1 + z)));
    return {s * std::cos(phi), s * std::sin(phi), z};
}

}  // namespace rayset::lightmodel
