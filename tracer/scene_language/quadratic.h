// The real roots of a t^2 + b t + c, in the form that loses no digits to cancellation
// (q = -(b + sign(b) sqrt(b^2 - 4ac)) / 2, roots q / a and c / q), for the shapes' exact hits.
#pragma once

#include <cmath>
#include <utility>

namespace rayset::tracer {

// Writes the roots in increasing order into `roots`; returns how many (0, 1 or 2). With a = 0,
// the linear root.
inline int solve_quadratic(double a, double b, double c, double roots[2]) {
    if (a == 0) {
        if (b == 0) return 0;
        roots[0] = -c / b;
        return 1;
    }
    const double disc = b * b - 4 * a * c;
    if (disc < 0) return 0;
    const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
    roots[0] = q / a;
    if (q == 0) return 1;
    roots[1] = c / q;
    if (roots[1] < roots[0]) std::swap(roots[0], roots[1]);
    return 2;
}

}  // namespace rayset::tracer
