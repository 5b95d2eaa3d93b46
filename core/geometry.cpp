#include "core/geometry.h"

namespace rayset {

void orthonormal_basis(Vec3 axis, Vec3& u, Vec3& v) {
    const double sign = std::copysign(1.0, axis.z);
    const double a = -1 / (sign + axis.z);
    const double b = axis.x * axis.y * a;
    u = {1 + sign * axis.x * axis.x * a, sign * b, -sign * axis.x};
    v = {b, sign + axis.y * axis.y * a, -axis.y};
}

}  // namespace rayset
