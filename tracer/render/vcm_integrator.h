// Vertex connection and merging (Georgiev, Krivanek, Davidovic & Slusallek 2012, "Light
// transport simulation with vertex connection and merging", ACM TOG 31(6)): bidirectional path
// tracing and photon merging in one estimator, every strategy weighted against all the others
// by the balance heuristic, over every light of the scene (light.h) and the materials the other
// integrators use.
//
// A pass first traces its light subpaths (as many as it has camera samples, at least 65536) and
// keeps their vertices at surfaces with a smooth lobe. Each camera path then, at every vertex
// with a smooth lobe,
//   samples a light (next-event estimation),
//   connects to every vertex of one of the pass's light subpaths, drawn at random,
// and at its first smooth scene surface alone also
//   merges with the pass's light vertices within the gather radius (gather_radius.h);
// a segment that crosses a light's body adds its radiance. The weights are the recursive
// partial weights (dVCM, dVC, dVM) of the authors' technical report ("Implementing vertex
// connection and merging", 2012) and their SmallVCM, with merging a strategy at one vertex of
// a path only: the first smooth scene surface seen from the camera or, for a receiver point,
// the first after it. So a light subpath's vertex is never where its path merges, except the
// one a receiver point connects to. Merging carries the caustics seen there, directly or
// through mirrors and glass (light -> specular -> smooth <- camera); at later vertices
// connections carry the same light for less (in examples/led_box.pov, merging at every smooth
// vertex took 1.65 times the time of a pass for 0.8 of the variance). Nor does a light
// subpath's first vertex merge: light straight from a light is sampled or met on a segment,
// unbiased, where a merge would lose what lands within the radius beyond a surface's edge.
//
// Light densities are taken per unit area across the ray (light.h: pdf_Le), so no cosine at a
// light enters; a ray source, whose light along a line is an integral through its emitting
// volume, takes part as a light with a body does. Its light subpaths carry what a camera sees
// along their first segment (radiance over density, nothing where the line misses the body),
// so that all strategies estimate the one light field that light sampling and its body define.
//
// Left out, and so absent from the weights too: connecting light vertices to the camera (light
// tracing), and merging at a receiver cell's point (not a surface where light subpaths end).
//
// The light components are the path integrator's, read along the camera path: a body met
// through specular bounces only is direct visibility; light that reaches the first smooth
// vertex straight from a light (a light sample, a body met on the next segment) is primary;
// the rest is secondary.
#pragma once

#include <memory>

#include "tracer/render/integrator.h"
#include "tracer/render/render_scene.h"

namespace rayset::tracer {

// Throws rayset::Error for what it does not render (the path integrator does): spectral
// transport, interior fade and media, fog, shadowless lights, the naive ray set.
std::unique_ptr<Integrator> make_vcm_integrator(const RenderScene& scene,
                                                const RenderSettings& settings,
                                                const RenderResult& start);

}  // namespace rayset::tracer
