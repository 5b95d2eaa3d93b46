// Linear sRGB <-> CIE XYZ (see srgb.h).
#include "lightmodel/srgb.h"

namespace rayset::lightmodel {

namespace {

struct Matrix3 {
    double m[3][3];
};

Matrix3 inverse(const double a[3][3]) {
    Matrix3 r;
    const double det = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
                       a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
                       a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const int i1 = (j + 1) % 3, i2 = (j + 2) % 3, j1 = (i + 1) % 3, j2 = (i + 2) % 3;
            r.m[i][j] = (a[i1][j1] * a[i2][j2] - a[i1][j2] * a[i2][j1]) / det;
        }
    return r;
}

}  // namespace

Xyz to_xyz(const Rgb& c) {
    const auto& m = kSrgbToXyz;
    return {m[0][0] * c.red + m[0][1] * c.green + m[0][2] * c.blue,
            m[1][0] * c.red + m[1][1] * c.green + m[1][2] * c.blue,
            m[2][0] * c.red + m[2][1] * c.green + m[2][2] * c.blue};
}

Rgb to_linear_srgb(const Xyz& c) {
    static const Matrix3 inverse_matrix = inverse(kSrgbToXyz);
    const auto& m = inverse_matrix.m;
    return {m[0][0] * c.x + m[0][1] * c.y + m[0][2] * c.z,
            m[1][0] * c.x + m[1][1] * c.y + m[1][2] * c.z,
            m[2][0] * c.x + m[2][1] * c.y + m[2][2] * c.z};
}

}  // namespace rayset::lightmodel
