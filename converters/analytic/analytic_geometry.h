// Geometry of the analytic test sources: the exact irradiance that uniform Lambertian polygons
// and disks produce at any point and receiver orientation.
//
// Units: lengths in mm, radiance in W/(mm^2 sr), irradiance in W/mm^2 (multiply by 1e6 for
// W/m^2). A receiver normal points into the half-space the receiver collects light from.
#pragma once

#include "core/geometry.h"

#include <vector>

namespace rayset::analytic {

// Irradiance at `point` on a receiver with unit `normal` from a simple planar polygon (convex or
// not) of uniform Lambertian `radiance` that emits from one side only: the side from which its
// vertices run counter-clockwise. Exact (Lambert's contour formula, see
// docs/synthetic-sources.md), after clipping the polygon to the receiver's front half-space
// (the zero-width bridges clipping leaves in a non-convex polygon cancel in the contour sum).
double polygon_irradiance(double radiance, const std::vector<Vec3>& vertices, Vec3 point,
                          Vec3 normal);

// Irradiance from a one-sided Lambertian disk of `radius` centred at `centre` that emits into
// the half-space its unit `axis` points to. Exact closed form of the contour integral, also
// when the receiver's plane cuts the disk.
double disk_irradiance(double radiance, Vec3 centre, Vec3 axis, double radius, Vec3 point,
                       Vec3 normal);

}  // namespace rayset::analytic
