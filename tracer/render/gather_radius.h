// Where the integrators that merge photons with camera paths (bidirectional, vcm) gather them:
// within a radius that shrinks pass after pass, from surfaces facing the same way.
//
// Progressive photon mapping in the probabilistic form of Knaus & Zwicker 2011 ("Progressive
// photon mapping: a probabilistic approach", ACM TOG 30(3)): all gathers of pass i use one radius
// r_i, and the image is the average of the passes. r_{i+1}^2 = r_i^2 (i + alpha) / (i + 1) with
// alpha = 2/3 (the rule and value of Hachisuka, Ogaki & Jensen 2008, "Progressive photon
// mapping"), so both the variance and the bias of the average vanish as passes grow.
#pragma once

#include <vector>

#include "core/geometry.h"
#include "tracer/film/film.h"

namespace rayset::tracer {

// Photons count at a point only if they landed on a surface facing nearly the same way (the
// cosine between the two normals at least this), so that light on a neighbouring wall near a
// corner is not spread onto this one.
constexpr double kSameSurfaceCos = 0.9;

// The radius after `passes_done` passes, the last of them gathered with `radius`.
double shrunk_radius(double radius, int passes_done);

// The gather radius of every pass of one render. A continued render goes on from the radius
// its last pass used (`passes_done` passes, the last gathered with `last_radius`); a new one
// starts from `radius`, where 0 means unknown until the integrator measures it over the first
// pass (default_radius) and sets it.
class PassRadius {
public:
    PassRadius(double radius, int passes_done, double last_radius)
        : first_(passes_done > 0 ? shrunk_radius(last_radius, passes_done) : radius),
          first_pass_(passes_done) {}
    bool known() const { return first_ > 0; }
    // The radius of this render's first pass.
    double first() const { return first_; }
    void set_first(double radius) { first_ = radius; }
    // The radius of `pass`, from the first pass's shrunk pass after pass.
    double at(int pass) const {
        double r = first_;
        for (int k = first_pass_ + 1; k <= pass; ++k) r = shrunk_radius(r, k);
        return r;
    }

private:
    double first_;
    int first_pass_;
};

// The first pass's radius when none is given: a hundredth of the diagonal of the box holding the
// middle 90% of `points` along each axis (where gathers happen), so that a floor plane seen to
// its horizon does not make every gather as wide as the floor; 1 without points.
double default_radius(std::vector<Vec3> points);

// The centres of the receivers' cells, which gather as pixels do: appended to `points`.
void append_receiver_cells(const std::vector<ReceiverMap>& receivers, std::vector<Vec3>& points);

}  // namespace rayset::tracer
