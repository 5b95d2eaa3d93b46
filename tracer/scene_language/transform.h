// 4x4 affine transforms in the convention the renderer uses (column vectors, p' = M p), and
// the POV-Ray transform statements (translate, rotate, scale, matrix) expressed in it.
//
// POV-Ray stores row-vector matrices (p' = p M); we store their transpose so that composing
// "A then B" is B * A, as in pbrt. POV-Ray's coordinates are kept as they are (left-handed,
// y up): nothing here mirrors an axis.
#pragma once

#include <array>

#include "converters/analytic/analytic_geometry.h"

namespace rayset::tracer {

struct Matrix4 {
    // Row-major storage of the column-vector matrix: m[4 * row + column].
    std::array<double, 16> m{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

    double operator()(int row, int column) const { return m[4 * row + column]; }
    double& operator()(int row, int column) { return m[4 * row + column]; }

    Vec3 point(Vec3 p) const;             // affine point: rotation/scale part plus translation
    Vec3 vector(Vec3 v) const;            // direction or edge: no translation
    Vec3 normal(Vec3 n) const;            // inverse transpose, not normalised
    Vec3 transpose_vector(Vec3 v) const;  // the linear part's transpose applied to v
    Matrix4 inverse() const;              // throws rayset::Error when singular
};

Matrix4 operator*(const Matrix4& a, const Matrix4& b);

Matrix4 translation(Vec3 offset);
Matrix4 scaling(Vec3 factors);
// POV-Ray's `rotate <a, b, c>`: degrees about x, then y, then z. Each elementary rotation is
// the usual matrix (about y: x' = x cos + z sin, z' = -x sin + z cos), so in POV-Ray's
// left-handed frame it turns clockwise when looking down the axis toward the origin
// (rotate 90*y maps +x to -z and +z to +x).
Matrix4 pov_rotation(Vec3 degrees);
// POV-Ray's vaxis_rotate: `degrees` about `axis` (any length), Rodrigues' formula, which
// agrees with pov_rotation about the coordinate axes.
Matrix4 axis_rotation(Vec3 axis, double degrees);
// POV-Ray's `matrix <m00, m01, m02, m10, ..., m32>`: 12 values of a row-vector matrix, the last
// three the translation (x' = m00 x + m10 y + m20 z + m30).
Matrix4 pov_matrix(const std::array<double, 12>& values);

}  // namespace rayset::tracer
