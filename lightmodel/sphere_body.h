// The source body: the union of every boundary cell's spheres, as one Embree 3 scene holding one
// sphere-point geometry (RTC_FORMAT_FLOAT4 x y z r), with the queries the emitter needs.
//
// What intersect() returns. Embree reports a sphere's surface wherever the ray crosses it, also
// the exit of a sphere the ray starts in and the inner surfaces where spheres overlap. The body
// is the union of the balls, and what a camera sees of it is where a ray *enters* the union
// from outside. intersect() therefore returns the first point of the segment (0, tmax] where it
// enters the union: for an origin outside the body that is Embree's nearest hit; for an origin
// inside (a ray leaving the body from a point on or in it) the stretch inside is skipped and the
// next entry returned, if any. The normal is the outward normal of the ball entered, so
// dot(normal, dir) <= 0. t, point and normal are recomputed in double precision from the ball.
// occluded() answers "would intersect() hit" in the same sense, each of Embree's hits confirmed
// in double precision as intersect() confirms its nearest one.
//
// A tracer that instances scene() gets Embree's raw sphere hits (inner surfaces included);
// rays that start outside the body see the same first hit as here.
//
// Directions must be unit vectors; t is then a distance in mm. Every query is const and keeps its
// state on the stack, so any number of threads may query one body at once.
#pragma once

#include "lightmodel/lattice.h"
#include "lightmodel/sphere.h"

#include <embree3/rtcore.h>

#include <cstdint>
#include <vector>

namespace rayset::lightmodel {

struct BodyHit {
    double t = 0;
    Vec3 point;
    Vec3 normal;          // outward unit normal of the ball entered
    uint32_t sphere = 0;  // index into spheres()
};

class SphereBody {
public:
    // `device`: the tracer's Embree device, so that it can instance scene() in its own scene
    // (an instance must live on the same device); nullptr creates a device of the body's own.
    explicit SphereBody(std::vector<Sphere> spheres, RTCDevice device = nullptr);
    ~SphereBody();
    SphereBody(const SphereBody&) = delete;
    SphereBody& operator=(const SphereBody&) = delete;

    const std::vector<Sphere>& spheres() const { return spheres_; }
    const Box& bounds() const { return bounds_; }  // box of all spheres (empty when none)
    RTCScene scene() const { return scene_; }
    RTCDevice device() const { return device_; }

    // Whether `p` lies strictly inside at least one ball.
    bool inside(Vec3 p) const;
    bool intersect(Vec3 origin, Vec3 dir, double tmax, BodyHit& hit) const;
    bool occluded(Vec3 origin, Vec3 dir, double tmax) const;
    // Indices (ascending, each once) of every ball the closed segment origin + t dir,
    // 0 <= t <= tmax, meets: the balls a light-sampling pdf along that segment sums over.
    // `out` is overwritten.
    void crossed_spheres(Vec3 origin, Vec3 dir, double tmax, std::vector<uint32_t>& out) const;

private:
    bool hit_from(uint32_t sphere, Vec3 origin, Vec3 dir, double t, BodyHit& hit) const;
    bool entry_after_inside(Vec3 origin, Vec3 dir, double tmax, BodyHit& hit) const;

    std::vector<Sphere> spheres_;
    Box bounds_;
    float max_radius_ = 0;
    RTCDevice device_ = nullptr;
    RTCScene scene_ = nullptr;
};

}  // namespace rayset::lightmodel
