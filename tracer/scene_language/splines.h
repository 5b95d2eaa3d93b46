// POV-Ray's splines (reference manual 3.3.1.11): points with parameter values, evaluated as
// POV-Ray evaluates them (established from its output, see splines.cpp).
#pragma once

#include <vector>

#include "tracer/scene_language/values.h"

namespace rayset::tracer {

struct Spline {
    enum class Type { linear, quadratic, cubic, natural };
    Type type = Type::linear;
    // Sorted by parameter; a second point at the same parameter replaces the first.
    std::vector<double> parameters;
    std::vector<Numeric> points;  // each promoted to `terms`
    int terms = 2;                // the most of any point (2 to 5)

    // The point at parameter t as `type` (or this spline's own type) interpolates it; beyond the
    // valid range, the nearest valid end.
    Numeric evaluate(double t) const { return evaluate(t, type); }
    Numeric evaluate(double t, Type as) const;
};

}  // namespace rayset::tracer
