// Sampled wavelengths and the film's spectral -> RGB conversion (see spectrum.h).
#include "tracer/render/spectrum.h"

#include "lightmodel/colour.h"

namespace rayset::tracer {

namespace {

constexpr double kRange = kLambdaMax - kLambdaMin;

// IEC 61966-2-1 linear sRGB -> XYZ; its middle row is the luminance weights of rgb.h.
constexpr double kRgbToXyz[3][3] = {{0.4124, 0.3576, 0.1805}, {0.2126, 0.7152, 0.0722}, {0.0193, 0.1192, 0.9505}};

struct Matrix3 {
    double m[3][3];
};

Matrix3 inverse(const double a[3][3]) {
    Matrix3 r;
    const double det = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
                       a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const int i1 = (j + 1) % 3, i2 = (j + 2) % 3, j1 = (i + 1) % 3, j2 = (i + 2) % 3;
            r.m[i][j] = (a[i1][j1] * a[i2][j2] - a[i1][j2] * a[i2][j1]) / det;
        }
    return r;
}

const Matrix3& xyz_to_rgb_matrix() {
    static const Matrix3 m = inverse(kRgbToXyz);
    return m;
}

}  // namespace

SampledWavelengths SampledWavelengths::sample(const lightmodel::BinnedSpectrum& density, double u) {
    SampledWavelengths w;
    const double hero = density.sample(u);
    for (int i = 0; i < kWavelengths; ++i) {
        double nm = hero + i * kRange / kWavelengths;
        if (nm >= kLambdaMax) nm -= kRange;
        w.nm[i] = float(nm);
        w.pdf[i] = float(density.pdf(w.nm[i]));
    }
    return w;
}

SampledWavelengths SampledWavelengths::single(double nm) {
    SampledWavelengths w;
    std::fill(w.nm, w.nm + kWavelengths, float(nm));
    w.pdf[0] = 1;
    return w;
}

CieXyz cie_xyz(double nm) {
    const lightmodel::Xyz c = lightmodel::colour_matching(nm);
    const bool inside = nm >= kLambdaMin && nm <= kLambdaMax;
    return {inside ? std::max(0.0, c.x) : 0, lightmodel::photopic(nm), inside ? std::max(0.0, c.z) : 0};
}

Rgb xyz_to_rgb(const CieXyz& c) {
    const auto& m = xyz_to_rgb_matrix().m;
    return {m[0][0] * c.x + m[0][1] * c.y + m[0][2] * c.z, m[1][0] * c.x + m[1][1] * c.y + m[1][2] * c.z,
            m[2][0] * c.x + m[2][1] * c.y + m[2][2] * c.z};
}

CieXyz rgb_to_xyz(const Rgb& c) {
    const auto& m = kRgbToXyz;
    return {m[0][0] * c.red + m[0][1] * c.green + m[0][2] * c.blue, m[1][0] * c.red + m[1][1] * c.green + m[1][2] * c.blue,
            m[2][0] * c.red + m[2][1] * c.green + m[2][2] * c.blue};
}

Rgb to_rgb(const SampledSpectrum& value, const SampledWavelengths& w) {
    const double pdf_sum = w.pdf_sum();
    if (!(pdf_sum > 0)) return {};
    CieXyz sum;
    for (int i = 0; i < kWavelengths; ++i) {
        if (value.v[i] == 0) continue;
        const CieXyz c = cie_xyz(w.nm[i]);
        sum.x += c.x * value.v[i], sum.y += c.y * value.v[i], sum.z += c.z * value.v[i];
    }
    return xyz_to_rgb({sum.x / pdf_sum, sum.y / pdf_sum, sum.z / pdf_sum});
}

Rgb throughput_to_rgb(const SampledSpectrum& value, const SampledWavelengths& w) {
    CieXyz light, lit;
    for (int i = 0; i < kWavelengths; ++i) {
        if (!(w.pdf[i] > 0)) continue;
        const double d65 = lightmodel::illuminant_d65(w.nm[i]);
        const CieXyz c = cie_xyz(w.nm[i]);
        light.x += c.x * d65, light.y += c.y * d65, light.z += c.z * d65;
        lit.x += c.x * d65 * value.v[i], lit.y += c.y * d65 * value.v[i], lit.z += c.z * d65 * value.v[i];
    }
    // White (1, 1, 1) in XYZ, scaled coordinate by coordinate by the throughput's ratios.
    const CieXyz white = rgb_to_xyz({1, 1, 1});
    auto ratio = [](double a, double b) { return b > 0 ? a / b : 0; };
    return xyz_to_rgb({white.x * ratio(lit.x, light.x), white.y * ratio(lit.y, light.y), white.z * ratio(lit.z, light.z)});
}

}  // namespace rayset::tracer
