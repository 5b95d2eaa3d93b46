// The integrator interface: what one light-transport algorithm computes, for the one pass
// driver (renderer.h) that owns tiles, receivers, films, layers, budget, checkpoints and
// progress.
//
// A pass draws samples_per_pass() camera samples at every pixel and receiver cell, each from
// the random stream of its sample point; every sample adds its light to the pass's values,
// split into the integrator's components. Then the integrator may finish the pass with work
// over all of it (the bidirectional integrator traces photons and gathers them at the
// pass's visible points). The driver adds the pass to the films only once it is complete.
#pragma once

#include <algorithm>
#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/random.h"
#include "tracer/film/film.h"
#include "tracer/render/camera.h"
#include "tracer/render/sampler.h"
#include "tracer/render/spectrum.h"

namespace rayset::tracer {

class RenderScene;
struct RenderSettings;
struct RenderResult;

// The sample points of a pass: the pixels (when the image is rendered) in row order, then the
// receiver cells, receiver after receiver, row by row. Pixel p draws from random stream p,
// receiver cell c from stream first_cell_stream + c.
struct SamplePoints {
    int width = 0, height = 0;  // the image; 0 x 0 for a receivers-only render
    int tile_size = 16;
    uint64_t first_cell_stream = 0;  // the image size, rendered or not
    const std::vector<ReceiverMap>* receivers = nullptr;
    std::vector<size_t> receiver_first;  // index of each receiver's first cell among the cells

    SamplePoints(const RenderSettings& settings, const std::vector<ReceiverMap>& receivers);
    size_t pixels() const { return size_t(width) * height; }
    size_t cells() const;
    size_t size() const { return pixels() + cells(); }
    int tiles_x() const { return (width + tile_size - 1) / tile_size; }
    int tiles() const { return tiles_x() * ((height + tile_size - 1) / tile_size); }
};

// The light components every integrator keeps apart (the paper's decomposition), the first
// three written out as layers:
//   direct visibility  a light's body seen from the camera, through specular chains only;
//   primary            light straight from a light to the first smooth (non-delta) scattering
//                      of a camera path (or a receiver point), reflected there;
//   secondary          light that scattered smoothly before that;
//   unlayered          light of no layer: emitting surfaces, the background, fog, media
//                      emission.
enum LightComponent { kDirectVisibility, kPrimary, kSecondary, kUnlayered, kLightComponents };
// The names of the layers, in that order.
const std::vector<std::string>& light_layers();

// The layers read along a camera path. `segment` is the component of a light's body met on the
// path's current segment: kDirectVisibility from the camera on, until the first smooth
// scattering.
// The component of light sampled (or connected, or merged) at the segment's end vertex.
inline LightComponent layer_of_light_at_vertex(LightComponent segment) {
    return segment == kDirectVisibility ? kPrimary : kSecondary;
}
// The component of the next segment after the path scattered, specularly (delta) or not.
inline LightComponent layer_after_scattering(LightComponent segment, bool delta) {
    return segment != kDirectVisibility ? kSecondary : delta ? kDirectVisibility : kPrimary;
}

// The fewest light paths (photons) an integrator that traces light from the lights starts in a
// pass: a small image's pass would otherwise carry too few to gather from.
constexpr uint64_t kMinimumLightPathsPerPass = 65536;

// The light paths a pass of such an integrator starts, and the camera samples per pixel and
// receiver cell that balance them: the settings' photons a pass when given, else one for each
// sample point but at least kMinimumLightPathsPerPass; as many camera samples as make the
// pass's camera paths about as many as its light paths, at least one. A small image or a
// receiver-only render so takes several samples in each pass rather than leave the light paths
// (and their fixed cost) to dominate.
struct LightPathBudget {
    uint64_t light_paths = 0;
    int camera_samples = 1;
};
LightPathBudget light_path_budget(const RenderScene& scene, const RenderSettings& settings);

// The most vertices a path may have in any integrator: a cap far beyond what Russian roulette
// lets live.
constexpr int kMaxPathVertices = 256;

// Russian roulette on a camera path's throughput `beta` (Rgb or SampledSpectrum): the path goes
// on with probability min(0.95, the largest component), `beta` then divided by it.
template <class Q>
bool survives_roulette(Q& beta, Pcg32& rng) {
    const double survive = std::min(0.95, max_component(beta));
    if (rng.uniform_float() >= survive) return false;
    beta = (1 / survive) * beta;
    return true;
}

// A quantity Q (Rgb, or SampledSpectrum at a path's wavelengths) split by LightComponent.
template <class Q>
struct LightComponentsOf {
    std::array<Q, kLightComponents> of{};

    LightComponentsOf& operator+=(const LightComponentsOf& other) {
        for (int c = 0; c < kLightComponents; ++c) of[size_t(c)] += other.of[size_t(c)];
        return *this;
    }
    friend LightComponentsOf operator*(double k, const LightComponentsOf& a) {
        LightComponentsOf scaled;
        for (int c = 0; c < kLightComponents; ++c) scaled.of[size_t(c)] = k * a.of[size_t(c)];
        return scaled;
    }
    Q total() const {
        Q sum = of[0];
        for (int c = 1; c < kLightComponents; ++c) sum += of[size_t(c)];
        return sum;
    }
};

// Each component made linear sRGB (spectrum.h's to_rgb).
template <class Q>
LightComponentsOf<Rgb> to_rgb(const LightComponentsOf<Q>& light,
                              const WavelengthsFor<Q>& wavelengths) {
    LightComponentsOf<Rgb> rgb;
    for (int c = 0; c < kLightComponents; ++c)
        rgb.of[size_t(c)] = to_rgb(light.of[size_t(c)], wavelengths);
    return rgb;
}

// A pass's light at every sample point, renderer units: one array per component.
struct PassValues {
    std::vector<std::vector<Rgb>> components;
    PassValues(int components, size_t points);
    // The light of point i: the sum of its components in their order.
    Rgb total(size_t i) const;
};

// Where one camera sample's light goes: sample point `index` (of tile `tile` for a pixel, -1
// for a receiver cell), each value weighted by 1 / samples per pass.
struct SampleSink {
    PassValues& values;
    size_t index;
    int tile;
    double weight;
    void add(int component, Rgb value) const {
        values.components[size_t(component)][index] += weight * value;
    }
};

// Once true, the pass under way is abandoned (RenderControl::stop).
using StopFlag = const std::atomic<bool>*;
inline bool stopped(StopFlag stop) { return stop && stop->load(std::memory_order_relaxed); }

class Integrator {
public:
    virtual ~Integrator() = default;

    // The pass values hold one component per layer of the integrator (integrator_layers), in
    // that order, and one more, the last, for light in no layer; the film holds their sum.

    // Camera samples per pixel and receiver cell in each pass.
    virtual int samples_per_pass() const { return 1; }

    // Before a pass's samples, inside the driver's thread arena (the vcm integrator traces the
    // pass's light subpaths here; `rays` counts their rays).
    virtual void begin_pass(int /*pass*/, const SamplePoints& /*points*/,
                            std::atomic<uint64_t>& /*rays*/) {}
    // One camera ray's light (and whatever the integrator keeps of it for end_pass), its
    // random numbers from `sampler` (the pixel's position took its first pair). Called
    // concurrently for different tiles and receiver cells.
    virtual void camera_sample(const CameraRay& ray, const SampleSink& sink, Sampler& sampler,
                               uint64_t& rays) const = 0;
    // One sample of the irradiance at a receiver cell's centre `point`, from the side `normal`
    // points into. Called concurrently for different cells.
    virtual void receiver_sample(Vec3 point, Vec3 normal, const SampleSink& sink, Sampler& sampler,
                                 uint64_t& rays) const = 0;
    // After every sample of the pass: work over the whole pass, inside the driver's thread
    // arena; returns early (the pass is then dropped) once `stop` is set.
    virtual void end_pass(int /*pass*/, const SamplePoints& /*points*/, PassValues& /*values*/,
                          std::atomic<uint64_t>& /*rays*/, StopFlag /*stop*/) {}
    // Pass result.passes - 1 is complete (rendered here or by another process): the
    // integrator's own figures into `result`.
    virtual void pass_completed(RenderResult& /*result*/) {}

    // Whether passes take something from the first one (the bidirectional integrator's gather
    // radius, derived from the first pass's visible points unless given). The process that
    // renders the first pass is asked first_pass_outcome() once its samples are in, and every
    // process, before its pass ends, is handed it.
    virtual bool first_pass_sets_outcome() const { return false; }
    virtual std::vector<double> first_pass_outcome() { return {}; }
    virtual void set_first_pass_outcome(const std::vector<double>& /*outcome*/) {}
};

// The integrators by the name global_settings { integrator NAME } gives: "path" (the
// default), "bidirectional" or "vcm". `start`: the state a continued render goes on from.
std::unique_ptr<Integrator> make_integrator(const RenderScene& scene,
                                            const RenderSettings& settings,
                                            const RenderResult& start);
// The light components the integrator of that name keeps apart, each written out as a layer
// (its own image and receiver maps); known before the scene is built (checkpoints).
std::vector<std::string> integrator_layers(const std::string& name);
// Whether paths carry spectra (--spectral or global_settings { spectral on }) or RGB.
bool spectral_transport(const RenderScene& scene, const RenderSettings& settings);
// Throws for what an integrator that traces light from the lights does not render and the path
// integrator does: a shadowless light (its light reaches a point through any occluder, which no
// light path does) and fog (light paths are not dimmed along their segments).
void refuse_what_light_paths_do_not_carry(const RenderScene& scene, const std::string& integrator);

}  // namespace rayset::tracer
