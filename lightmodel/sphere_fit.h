// The spheres of one boundary cell: how many (following the cell's density) and where (a Ceres
// fit against a sample of the origins that fell in the cell).
//
// The fit, in units of the cell size h (positions relative to the cell's lower corner):
//  1. footprint delta = footprint x the samples' spacing: their mean nearest-neighbour distance,
//     at most 0.5 / sqrt(n) (n samples spread evenly over a flat cell; 0.5 for a lone sample). A
//     sample stands for the surface around it up to about one spacing, so covering the samples
//     plus delta leaves (almost) no holes between them.
//     Measured on flat 3x3 blocks of cells, 64 samples and K = 16 each: footprint 0.5 leaves
//     32% of the surface uncovered, 1.5 4%, 2 (default) 1%, 3 none, at layer thicknesses
//     0.23, 0.30, 0.34 and 0.41 h.
//  2. centres by farthest-point selection among the samples: first the sample nearest their
//     centroid, then repeatedly the sample farthest from every centre chosen so far (centres as
//     far apart as possible); at most min(K, distinct samples) centres. Each sample belongs to
//     its nearest centre.
//  3. Ceres moves each centre to where its farthest sample is nearest: it minimises, from the
//     centroid of each sphere's samples,
//        sum_k sum_{i of k} (|p_i - c_k| / s_k)^(2m)      (s_k: the sphere's first radius, m = 4)
//     a smooth convex stand-in for max_i |p_i - c_k| (the L_2m norm tends to the maximum), whose
//     minimiser approaches the centre of the smallest ball enclosing the samples. It is posed as
//     residuals (c_k - p_i) / s_k, linear in the centre, under the loss rho(s) = s^m, so that
//     Ceres' loss correction gives Newton steps: 3 iterations suffice. The minimiser lies in the
//     samples' convex hull, hence in the cell: no bounds needed. A sphere of one or two samples
//     is exact at their centroid and left out of the problem.
//  4. the radii are then eliminated exactly: samples are reassigned to the nearest fitted
//     centre and each radius is set to its farthest sample plus delta, so every sample is
//     covered whatever the solver's tolerance; a sphere left without samples is dropped.
// A flat layer of samples thus gives a layer of spheres about 2 x (h / sqrt(K) / 2 + delta)
// thick, not cells filled with spheres of radius h.
#pragma once

#include "lightmodel/lattice.h"
#include "lightmodel/sphere.h"

#include <vector>

namespace rayset::lightmodel {

struct SphereFitOptions {
    double footprint = 2.0;  // delta as a multiple of the samples' mean nearest-neighbour distance
    int power = 4;           // m: the spread is the L_2m norm of the distances
    int max_iterations = 5;
    double function_tolerance = 1e-3;
};

// Spheres (world coordinates, mm) of the cell whose lower corner is `cell_lower` and edge
// `cell_size`, fitted to `samples` (the origins sampled in the cell, at least one).
std::vector<Sphere> fit_cell_spheres(Vec3 cell_lower, double cell_size,
                                     const std::vector<Vec3>& samples, int sphere_count,
                                     const SphereFitOptions& options = {});

// Spheres for a boundary cell holding `count` rays: K = clamp(round(max_spheres x count /
// reference_count), 1, max_spheres), so the densest boundary cells get the most spheres and a
// cell the source barely touches gets one. `reference_count` comes from reference_count().
int spheres_for_count(double count, double reference_count, int max_spheres = 16);

// The `quantile` (0..1) of the boundary cells' counts: a high quantile rather than the maximum,
// so that one hot cell does not leave every other cell with a single sphere.
double reference_count(std::vector<double> counts, double quantile = 0.9);

}  // namespace rayset::lightmodel
