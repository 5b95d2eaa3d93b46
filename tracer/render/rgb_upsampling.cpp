// Jakob-Hanika RGB -> spectrum upsampling (see rgb_upsampling.h).
#include "tracer/render/rgb_upsampling.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <mutex>
#include <tuple>

#include "tracer/render/spectrum.h"

namespace rayset::tracer {

namespace {

constexpr int kSteps = 471;  // 1 nm from 360 to 830

double normalised(double nm) { return (nm - kLambdaMin) / (kLambdaMax - kLambdaMin); }
double sigmoid(double x) { return 0.5 + x / (2 * std::sqrt(1 + x * x)); }
double sigmoid_slope(double x) { return 0.5 / std::pow(1 + x * x, 1.5); }

// w[k][i]: weight of wavelength 360 + i nm in channel k, the sRGB matching function (XYZ ->
// linear sRGB of the CIE functions) x D65, each channel summing to 1.
struct ChannelWeights {
    std::array<std::array<double, kSteps>, 3> w{};
    ChannelWeights() {
        for (int i = 0; i < kSteps; ++i) {
            const double nm = kLambdaMin + i;
            const CieXyz c = cie_xyz(nm);
            const double d65 = lightmodel::illuminant_d65(nm);
            const Rgb m = xyz_to_rgb({c.x * d65, c.y * d65, c.z * d65});
            w[0][size_t(i)] = m.red, w[1][size_t(i)] = m.green, w[2][size_t(i)] = m.blue;
        }
        for (auto& channel : w) {
            double sum = 0;
            for (double x : channel) sum += x;
            for (double& x : channel) x /= sum;
        }
    }
};
const ChannelWeights& weights() {
    static const ChannelWeights w;
    return w;
}

// Colour of the sigmoid spectrum with coefficients c, and its Jacobian d colour / d c.
void colour_and_jacobian(const double c[3], double rgb[3], double jacobian[3][3]) {
    const ChannelWeights& w = weights();
    for (int k = 0; k < 3; ++k) {
        rgb[k] = 0;
        for (int j = 0; j < 3; ++j) jacobian[k][j] = 0;
    }
    for (int i = 0; i < kSteps; ++i) {
        const double t = normalised(kLambdaMin + i), x = (c[0] * t + c[1]) * t + c[2];
        const double rho = sigmoid(x), slope = sigmoid_slope(x);
        const double dx[3] = {t * t, t, 1};
        for (int k = 0; k < 3; ++k) {
            const double wk = w.w[size_t(k)][size_t(i)];
            rgb[k] += wk * rho;
            for (int j = 0; j < 3; ++j) jacobian[k][j] += wk * slope * dx[j];
        }
    }
}

// Solves a 3x3 system by Cramer's rule; false if singular.
bool solve3(const double a[3][3], const double b[3], double x[3]) {
    auto det = [](const double m[3][3]) {
        return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
               m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
               m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    };
    const double d = det(a);
    if (!(std::fabs(d) > 1e-300)) return false;
    for (int j = 0; j < 3; ++j) {
        double m[3][3];
        for (int r = 0; r < 3; ++r)
            for (int col = 0; col < 3; ++col) m[r][col] = col == j ? b[r] : a[r][col];
        x[j] = det(m) / d;
    }
    return true;
}

double squared_error(const double c[3], const double target[3]) {
    double rgb[3], jacobian[3][3];
    colour_and_jacobian(c, rgb, jacobian);
    double e = 0;
    for (int k = 0; k < 3; ++k) e += (rgb[k] - target[k]) * (rgb[k] - target[k]);
    return e;
}

// Levenberg-Marquardt from c toward the coefficients whose colour is `target`.
void refine(double c[3], const double target[3], int iterations) {
    double lambda = 1e-3;
    for (int it = 0; it < iterations; ++it) {
        double rgb[3], jacobian[3][3];
        colour_and_jacobian(c, rgb, jacobian);
        double r[3], error = 0;
        for (int k = 0; k < 3; ++k) r[k] = rgb[k] - target[k], error += r[k] * r[k];
        if (error < 1e-14) return;
        double jtj[3][3], jtr[3];
        for (int a = 0; a < 3; ++a) {
            jtr[a] = 0;
            for (int k = 0; k < 3; ++k) jtr[a] -= jacobian[k][a] * r[k];
            for (int b = 0; b < 3; ++b) {
                jtj[a][b] = 0;
                for (int k = 0; k < 3; ++k) jtj[a][b] += jacobian[k][a] * jacobian[k][b];
            }
        }
        bool improved = false;
        for (int attempt = 0; attempt < 20 && !improved; ++attempt) {
            double damped[3][3], step[3];
            for (int a = 0; a < 3; ++a)
                for (int b = 0; b < 3; ++b)
                    damped[a][b] = jtj[a][b] + (a == b ? lambda * (jtj[a][a] + 1e-12) : 0);
            if (solve3(damped, jtr, step)) {
                const double next[3] = {c[0] + step[0], c[1] + step[1], c[2] + step[2]};
                if (squared_error(next, target) < error) {
                    c[0] = next[0], c[1] = next[1], c[2] = next[2];
                    lambda = std::max(1e-9, lambda / 4);
                    improved = true;
                    continue;
                }
            }
            lambda *= 8;
        }
        if (!improved) return;
    }
}

ReflectanceSpectrum fit(const double target[3]) {
    if (target[0] == target[1] && target[1] == target[2])
        return ReflectanceSpectrum::constant(target[0]);
    // Continuation from the colour's grey (a constant, c0 = c1 = 0) to the colour itself.
    const double grey = std::clamp((target[0] + target[1] + target[2]) / 3, 1e-3, 1 - 1e-3);
    double c[3] = {0, 0, (grey - 0.5) / std::sqrt(grey * (1 - grey))};  // S(c2) = grey
    constexpr int kStages = 16;
    for (int s = 1; s <= kStages; ++s) {
        const double f = double(s) / kStages;
        const double step_target[3] = {grey + f * (target[0] - grey), grey + f * (target[1] - grey),
                                       grey + f * (target[2] - grey)};
        refine(c, step_target, s == kStages ? 200 : 30);
    }
    return ReflectanceSpectrum::sigmoid(c[0], c[1], c[2]);
}

}  // namespace

ReflectanceSpectrum ReflectanceSpectrum::constant(double value) {
    ReflectanceSpectrum s;
    s.constant_ = std::clamp(value, 0.0, 1.0);
    return s;
}

ReflectanceSpectrum ReflectanceSpectrum::sigmoid(double c0, double c1, double c2) {
    ReflectanceSpectrum s;
    s.c_[0] = c0, s.c_[1] = c1, s.c_[2] = c2;
    s.constant_ = -1;
    return s;
}

double ReflectanceSpectrum::operator()(double nm) const {
    if (constant_ >= 0) return constant_;
    const double t = normalised(nm);
    return tracer::sigmoid((c_[0] * t + c_[1]) * t + c_[2]);
}

ReflectanceSpectrum upsample_reflectance(Rgb colour) {
    const double target[3] = {std::clamp(colour.red, 0.0, 1.0), std::clamp(colour.green, 0.0, 1.0),
                              std::clamp(colour.blue, 0.0, 1.0)};
    static std::mutex mutex;
    static std::map<std::tuple<double, double, double>, ReflectanceSpectrum> cache;
    const auto key = std::make_tuple(target[0], target[1], target[2]);
    {
        const std::lock_guard<std::mutex> lock(mutex);
        if (const auto it = cache.find(key); it != cache.end()) return it->second;
    }
    const ReflectanceSpectrum s = fit(target);
    const std::lock_guard<std::mutex> lock(mutex);
    return cache.emplace(key, s).first->second;
}

Rgb reflected_colour(const ReflectanceSpectrum& spectrum) {
    const ChannelWeights& w = weights();
    double rgb[3] = {0, 0, 0};
    for (int i = 0; i < kSteps; ++i) {
        const double rho = spectrum(kLambdaMin + i);
        for (int k = 0; k < 3; ++k) rgb[k] += w.w[size_t(k)][size_t(i)] * rho;
    }
    return {rgb[0], rgb[1], rgb[2]};
}

IlluminantSpectrum::IlluminantSpectrum(Rgb colour) {
    colour = {std::max(0.0, colour.red), std::max(0.0, colour.green), std::max(0.0, colour.blue)};
    scale_ = std::max({colour.red, colour.green, colour.blue});
    if (scale_ > 0) shape_ = upsample_reflectance((1 / scale_) * colour);
}

double IlluminantSpectrum::operator()(double nm) const {
    static const lightmodel::BinnedSpectrum d65 = lightmodel::d65_spectrum();
    return scale_ > 0 ? scale_ * shape_(nm) * d65(nm) : 0;
}

SampledSpectrum emitted(const Rgb& colour, const IlluminantSpectrum& spectrum,
                        const SampledWavelengths& w) {
    SampledSpectrum s;
    if (is_black(colour)) return s;
    for (int i = 0; i < kWavelengths; ++i) s.v[i] = spectrum(w.nm[i]);
    return s;
}

}  // namespace rayset::tracer
