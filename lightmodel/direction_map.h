// The equal-area octahedral map between the unit sphere and the unit square [0,1]^2 (Clarberg
// 2008, "Fast equal-area mapping of the (hemi)sphere using SIMD"), on which goniometric diagrams
// are tabulated, and the folding of the square's edges that makes neighbour lookups continuous.
//
// Layout: the square's centre is +z, the inner diamond |2x-1| + |2y-1| <= 1 is the upper
// hemisphere, the four corner triangles the lower one (folded outward), and all four corners
// are -z. The Jacobian is constant: dOmega = 4 pi dA, so equal square areas are equal solid
// angles and a density over the square times 1/(4 pi) is a density over directions (sr^-1).
#pragma once

#include "converters/analytic/analytic_geometry.h"

namespace rayset::lightmodel {

struct Vec2 {
    double x = 0, y = 0;
};

inline constexpr double kSquareToSolidAngle = 4 * kPi;  // dOmega / dA

// `w` must be a unit vector. The result lies in [0,1]^2. A direction of the lower hemisphere in
// the plane x = 0 or y = 0 lies on a folded edge and maps to one of its two edge points (-z to
// the corner (1, 1)); square_to_direction() takes both back to it.
Vec2 direction_to_square(Vec3 w);

// Any point of [0,1]^2 (points outside are clamped into it) to a unit direction. Points on the
// edges that the fold identifies, (x, 0) ~ (1-x, 0), (x, 1) ~ (1-x, 1), (0, y) ~ (0, 1-y),
// (1, y) ~ (1, 1-y), give the same direction.
Vec3 square_to_direction(Vec2 p);

// A point at most one square width outside [0,1]^2 brought back onto the square at the same
// place on the sphere: the fold across each edge is a reflection through the edge's midpoint,
// e.g. (x, 1 + e) ~ (1 - x, 1 - e) and (-e, y) ~ (e, 1 - y).
Vec2 wrap_square(Vec2 p);

// The same fold for the cells of an n x n grid of the square: cell (i, j) with i or j at most n
// cells outside [0, n) to the cell inside that covers the same directions.
struct CellIndex {
    int i = 0, j = 0;
};
CellIndex wrap_cell(CellIndex cell, int n);

}  // namespace rayset::lightmodel
