#include "converters/photometry/emit_distribution.h"

#include "converters/rays/io.h"
#include "core/error.h"
#include "core/geometry.h"

#include <algorithm>
#include <cmath>

namespace rayset {

namespace {

double wrap_360(double a) {
    a = std::fmod(a, 360.0);
    return a < 0 ? a + 360 : a;
}

// x in [0, 1] with density proportional to (1 - x) a + x b (a, b >= 0): the inverse of the
// quadratic cumulative, in the form that does not cancel when a is close to b.
double linear_sample(double u, double a, double b) {
    const double denominator = a + std::sqrt((1 - u) * a * a + u * b * b);
    return denominator > 0 ? std::min(1.0, u * (a + b) / denominator) : u;
}

enum class Symmetry { axial, quadrant, bilateral_0_180, bilateral_90_270, none };

Symmetry symmetry_of(const std::vector<double>& h) {
    if (h.size() == 1) return Symmetry::axial;
    if (h.front() == 0 && h.back() == 90) return Symmetry::quadrant;
    if (h.front() == 0 && h.back() == 180) return Symmetry::bilateral_0_180;
    if (h.front() == 90 && h.back() == 270) return Symmetry::bilateral_90_270;
    return Symmetry::none;
}

// The stored C angle whose values the C plane `c` (0..360) has under the symmetry.
double fold(Symmetry symmetry, double c) {
    switch (symmetry) {
        case Symmetry::quadrant:
            if (c > 180) c = 360 - c;
            return c > 90 ? 180 - c : c;
        case Symmetry::bilateral_0_180: return c > 180 ? 360 - c : c;
        case Symmetry::bilateral_90_270: return c < 90 || c > 270 ? wrap_360(180 - c) : c;
        default: return c;
    }
}

[[noreturn]] void fail_distribution(const std::string& name, const std::string& what) {
    throw Error(name + ": " + what);
}

// Only type C photometry with ascending angles and a full table of intensities >= 0 is sampled.
void check_distribution(const Photometry& p, const std::string& name) {
    if (p.type != PhotometricType::C)
        fail_distribution(name, std::string("type ") + (p.type == PhotometricType::A ? "A" : "B") +
                                    " photometry cannot be turned into rays: only type C is "
                                    "supported (convert the file to type C first)");
    const auto& h = p.horizontal_deg;
    const auto& v = p.vertical_deg;
    if (h.empty() || v.size() < 2)
        fail_distribution(name, "rays need at least two vertical angles and one horizontal angle");
    if (p.candela.size() != h.size() * v.size())
        fail_distribution(name, "the candela table does not match the angles");
    for (size_t j = 0; j < v.size(); ++j)
        if (!(v[j] >= 0 && v[j] <= 180) || (j && !(v[j] > v[j - 1])))
            fail_distribution(name, "vertical angle " + format_double(v[j]) +
                                        " is not ascending within 0..180 degrees");
    for (size_t i = 0; i < h.size(); ++i)
        if (!std::isfinite(h[i]) || (i && !(h[i] > h[i - 1])))
            fail_distribution(name,
                              "horizontal angle " + format_double(h[i]) + " is not ascending");
    if (h.back() - h.front() > 360)
        fail_distribution(name, "the horizontal angles span more than 360 degrees");
    for (double cd : p.candela)
        if (!(cd >= 0 && std::isfinite(cd)))
            fail_distribution(name, "candela value " + format_double(cd) + " is not a number >= 0");
}

// C nodes over one full turn: the stored planes and their mirror images.
std::vector<double> unfolded_c_nodes(const std::vector<double>& h, Symmetry symmetry) {
    if (symmetry == Symmetry::axial) return {0, 360};
    std::vector<double> c;
    if (symmetry == Symmetry::none) {
        // A closing plane (C360 after C0) is C0 again: LM-63 requires equal values, and taking
        // C0's keeps a table and its EULUMDAT form (which has no C360) the same, as
        // Photometry::intensity() does.
        for (double a : h)
            if (a < h.front() + 360) c.push_back(a);
        c.push_back(h.front() + 360);
        return c;
    }
    c = {0, 360};
    for (double a : h) {
        c.push_back(a);
        if (symmetry == Symmetry::bilateral_90_270) c.push_back(wrap_360(180 - a));
        if (symmetry == Symmetry::bilateral_0_180 || symmetry == Symmetry::quadrant)
            c.push_back(360 - a);
        if (symmetry == Symmetry::quadrant) c.insert(c.end(), {180 - a, 180 + a});
    }
    std::sort(c.begin(), c.end());
    const auto same = [](double a, double b) { return std::abs(a - b) < 1e-9; };
    c.erase(std::unique(c.begin(), c.end(), same), c.end());
    c.back() = 360;
    return c;
}

// The value at unfolded node k and gamma index j: the stored plane the node folds onto, or (for
// nodes that are not images of a stored plane, such as 0 for 90..270 files) the linear
// interpolation that Photometry::intensity() would give there.
double unfolded_value(const Photometry& p, Symmetry symmetry, const std::vector<double>& c,
                      size_t k, size_t j) {
    const auto& h = p.horizontal_deg;
    if (h.size() == 1) return p.candela[p.index(0, j)];
    // Without symmetry the nodes are the stored planes, then the first one again at +360.
    if (symmetry == Symmetry::none) return p.candela[p.index(k + 1 < c.size() ? k : 0, j)];
    const double a = std::clamp(fold(symmetry, c[k]), h.front(), h.back());
    size_t i = size_t(std::upper_bound(h.begin(), h.end(), a) - h.begin());
    i = std::min(i == 0 ? 0 : i - 1, h.size() - 2);
    const double t = (a - h[i]) / (h[i + 1] - h[i]);
    return (1 - t) * p.candela[p.index(i, j)] + t * p.candela[p.index(i + 1, j)];
}

}  // namespace

IntensityDistribution::IntensityDistribution(const Photometry& p, const std::string& name) {
    check_distribution(p, name);
    const Symmetry symmetry = symmetry_of(p.horizontal_deg);
    c_ = unfolded_c_nodes(p.horizontal_deg, symmetry);
    gamma_ = p.vertical_deg;
    values_.resize(c_.size() * gamma_.size());
    for (size_t k = 0; k < c_.size(); ++k)
        for (size_t j = 0; j < gamma_.size(); ++j)
            values_[k * gamma_.size() + j] = unfolded_value(p, symmetry, c_, k, j);
    integrate_cells();
    if (!(total_ > 0))
        fail_distribution(
            name, "the intensity table is zero everywhere: there is no light to turn into rays");
}

// Exact flux of each cell: the bilinear intensity integrates over C to the mean of its two edges,
// leaving the integrals of (1 - t) sin(gamma) and t sin(gamma) over the band.
void IntensityDistribution::integrate_cells() {
    const size_t bands = gamma_.size() - 1;
    std::vector<double> w0(bands), w1(bands);
    for (size_t j = 0; j < bands; ++j) {
        const double a = gamma_[j] * kRadiansPerDegree, b = gamma_[j + 1] * kRadiansPerDegree,
                     d = b - a;
        const double mean_sin = (std::sin(b) - std::sin(a)) / d;
        w0[j] = std::cos(a) - mean_sin;
        w1[j] = mean_sin - std::cos(b);
        sin_max_.push_back(gamma_[j + 1] <= 90 ? std::sin(b) : gamma_[j] >= 90 ? std::sin(a) : 1.0);
    }
    for (size_t k = 0; k + 1 < c_.size(); ++k) {
        const double dc = (c_[k + 1] - c_[k]) * kRadiansPerDegree;
        for (size_t j = 0; j < bands; ++j) {
            const double low = (value(k, j) + value(k + 1, j)) / 2;
            const double high = (value(k, j + 1) + value(k + 1, j + 1)) / 2;
            total_ += dc * (low * w0[j] + high * w1[j]);
            cumulative_.push_back(total_);
        }
    }
}

double IntensityDistribution::intensity(double c_deg, double gamma_deg) const {
    if (!(gamma_deg >= gamma_.front() && gamma_deg <= gamma_.back())) return 0;
    const double c = c_.front() + wrap_360(c_deg - c_.front());
    size_t k = size_t(std::upper_bound(c_.begin(), c_.end(), c) - c_.begin());
    k = std::min(k == 0 ? 0 : k - 1, c_.size() - 2);
    size_t j = size_t(std::upper_bound(gamma_.begin(), gamma_.end(), gamma_deg) - gamma_.begin());
    j = std::min(j == 0 ? 0 : j - 1, gamma_.size() - 2);
    const double s = (c - c_[k]) / (c_[k + 1] - c_[k]);
    const double t = (gamma_deg - gamma_[j]) / (gamma_[j + 1] - gamma_[j]);
    return (1 - s) * ((1 - t) * value(k, j) + t * value(k, j + 1)) +
           s * ((1 - t) * value(k + 1, j) + t * value(k + 1, j + 1));
}

void IntensityDistribution::sample(Pcg32& rng, double& c_deg, double& gamma_deg) const {
    const double target = rng.uniform() * total_;
    const size_t cell = std::min<size_t>(
        std::upper_bound(cumulative_.begin(), cumulative_.end(), target) - cumulative_.begin(),
        cumulative_.size() - 1);
    const size_t bands = gamma_.size() - 1;
    const size_t k = cell / bands, j = cell % bands;
    const double v00 = value(k, j), v01 = value(k, j + 1), v10 = value(k + 1, j),
                 v11 = value(k + 1, j + 1);
    // Within the cell: (s, t) from the bilinear intensity alone (t from its marginal, s given t),
    // then accepted with probability sin(gamma) / max sin(gamma), which leaves the density
    // proportional to intensity x sin(gamma), the flux per unit (C, gamma).
    for (;;) {
        const double t = linear_sample(rng.uniform(), (v00 + v10) / 2, (v01 + v11) / 2);
        const double s =
            linear_sample(rng.uniform(), (1 - t) * v00 + t * v01, (1 - t) * v10 + t * v11);
        const double gamma = gamma_[j] + t * (gamma_[j + 1] - gamma_[j]);
        if (rng.uniform() * sin_max_[j] >= std::sin(gamma * kRadiansPerDegree)) continue;
        gamma_deg = gamma;
        c_deg = wrap_360(c_[k] + s * (c_[k + 1] - c_[k]));
        return;
    }
}

}  // namespace rayset
