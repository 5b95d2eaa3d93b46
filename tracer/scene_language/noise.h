// Solid noise with the statistics of POV-Ray 3.7's: the noise behind bozo, granite, agate,
// turbulence and vturbulence.
//
// POV-Ray's manual gives no formula for its noise, and its lattice tables are its own, so the
// patterns cannot agree with POV-Ray's point for point. What they agree in is what a pattern
// shows: the distribution of values and how fast they decorrelate with distance (the power
// spectrum). The noise here is gradient noise on the integer lattice with a cubic blend
// (Perlin 1985) plus a lattice value term; the value term's weight, the scale and the mean of
// each generator were read back from POV-Ray (`function { pattern { bozo } }` and vturbulence
// at 20 000 random points; the test compares mean, spread and autocorrelation at four
// distances with POV-Ray's own).
#pragma once

#include "core/geometry.h"

namespace rayset::tracer {

// noise_generator 1 (POV-Ray's original noise: values clipped to [0, 1]), 2 (the same noise
// with its range corrected, POV-Ray's default) or 3 (Perlin's noise, less correlated at a
// lattice step). Any other number is taken as 2.
inline constexpr int kDefaultNoiseGenerator = 2;

// A value in [0, 1] (mean about 0.5, standard deviation 0.126 for generator 2).
double solid_noise(Vec3 point, int generator);

// Three independent noises centred on zero, each twice the spread of generator 2's. POV-Ray's
// vector noise is the same whatever noise_generator says (vturbulence gives the same values).
Vec3 vector_noise(Vec3 point);

// sum over i < octaves of omega^i vector_noise(lambda^i point): POV-Ray's vturbulence and the
// displacement of its turbulence. Octaves are taken within [1, 10], as POV-Ray takes them.
Vec3 vector_turbulence(Vec3 point, int octaves, double omega, double lambda);

// sum over i < octaves of omega^i solid_noise(lambda^i point), octaves within [1, 10].
double scalar_turbulence(Vec3 point, int octaves, double omega, double lambda, int generator);

// POV-Ray's crackle cells: one point in each unit cube of the lattice, uniform in it (read back
// from POV-Ray's statistics, like the noise above). The distances from `point` to the nearest
// three points in the Minkowski metric of exponent `metric`, each d taken as
// (d^metric + offset^metric)^(1 / metric), nearest first; and the nearest point.
struct CellDistances {
    double nearest[3];
    Vec3 nearest_point;
};
CellDistances cell_distances(Vec3 point, double metric, double offset);

}  // namespace rayset::tracer
