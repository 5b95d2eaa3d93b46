// Matrix4 arithmetic and the POV-Ray transform statements.
#include "tracer/scene_language/transform.h"

#include <cmath>

#include "core/error.h"

namespace rayset::tracer {

Vec3 Matrix4::point(Vec3 p) const {
    const Matrix4& a = *this;
    return {a(0, 0) * p.x + a(0, 1) * p.y + a(0, 2) * p.z + a(0, 3),
            a(1, 0) * p.x + a(1, 1) * p.y + a(1, 2) * p.z + a(1, 3),
            a(2, 0) * p.x + a(2, 1) * p.y + a(2, 2) * p.z + a(2, 3)};
}

Vec3 Matrix4::vector(Vec3 v) const {
    const Matrix4& a = *this;
    return {a(0, 0) * v.x + a(0, 1) * v.y + a(0, 2) * v.z,
            a(1, 0) * v.x + a(1, 1) * v.y + a(1, 2) * v.z,
            a(2, 0) * v.x + a(2, 1) * v.y + a(2, 2) * v.z};
}

Vec3 Matrix4::normal(Vec3 n) const { return inverse().transpose_vector(n); }

Vec3 Matrix4::transpose_vector(Vec3 v) const {
    const Matrix4& a = *this;
    return {a(0, 0) * v.x + a(1, 0) * v.y + a(2, 0) * v.z,
            a(0, 1) * v.x + a(1, 1) * v.y + a(2, 1) * v.z,
            a(0, 2) * v.x + a(1, 2) * v.y + a(2, 2) * v.z};
}

Matrix4 operator*(const Matrix4& a, const Matrix4& b) {
    Matrix4 r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            double sum = 0;
            for (int k = 0; k < 4; ++k) sum += a(i, k) * b(k, j);
            r(i, j) = sum;
        }
    return r;
}

Matrix4 Matrix4::inverse() const {
    // Gauss-Jordan with partial pivoting on [A | I].
    double a[4][8];
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 8; ++j) a[i][j] = j < 4 ? (*this)(i, j) : (j - 4 == i ? 1.0 : 0.0);
    for (int column = 0; column < 4; ++column) {
        int pivot = column;
        for (int row = column + 1; row < 4; ++row)
            if (std::fabs(a[row][column]) > std::fabs(a[pivot][column])) pivot = row;
        if (std::fabs(a[pivot][column]) < 1e-300) throw Error("singular transform matrix");
        for (int j = 0; j < 8; ++j) std::swap(a[column][j], a[pivot][j]);
        const double scale = 1.0 / a[column][column];
        for (int j = 0; j < 8; ++j) a[column][j] *= scale;
        for (int row = 0; row < 4; ++row) {
            if (row == column) continue;
            const double factor = a[row][column];
            for (int j = 0; j < 8; ++j) a[row][j] -= factor * a[column][j];
        }
    }
    Matrix4 r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) r(i, j) = a[i][j + 4];
    return r;
}

Matrix4 translation(Vec3 offset) {
    Matrix4 r;
    r(0, 3) = offset.x;
    r(1, 3) = offset.y;
    r(2, 3) = offset.z;
    return r;
}

Matrix4 scaling(Vec3 factors) {
    Matrix4 r;
    r(0, 0) = factors.x;
    r(1, 1) = factors.y;
    r(2, 2) = factors.z;
    return r;
}

Matrix4 pov_rotation(Vec3 degrees) {
    const double to_radians = kPi / 180.0;
    const double ax = degrees.x * to_radians, ay = degrees.y * to_radians,
                 az = degrees.z * to_radians;
    Matrix4 rx, ry, rz;
    rx(1, 1) = std::cos(ax), rx(1, 2) = -std::sin(ax), rx(2, 1) = std::sin(ax),
          rx(2, 2) = std::cos(ax);
    ry(0, 0) = std::cos(ay), ry(0, 2) = std::sin(ay), ry(2, 0) = -std::sin(ay),
          ry(2, 2) = std::cos(ay);
    rz(0, 0) = std::cos(az), rz(0, 1) = -std::sin(az), rz(1, 0) = std::sin(az),
          rz(1, 1) = std::cos(az);
    return rz * ry * rx;
}

Matrix4 axis_rotation(Vec3 axis, double degrees) {
    const Vec3 k = normalized(axis);
    const double angle = degrees * kPi / 180.0, c = std::cos(angle), s = std::sin(angle);
    const double kk[3] = {k.x, k.y, k.z};
    const double cross[3][3] = {{0, -k.z, k.y}, {k.z, 0, -k.x}, {-k.y, k.x, 0}};
    Matrix4 r;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            r(i, j) = (i == j ? c : 0.0) + s * cross[i][j] + (1 - c) * kk[i] * kk[j];
    return r;
}

Matrix4 pov_matrix(const std::array<double, 12>& v) {
    Matrix4 r;
    for (int row = 0; row < 4; ++row)
        for (int column = 0; column < 3; ++column) r(column, row) = v[3 * row + column];
    return r;
}

}  // namespace rayset::tracer
