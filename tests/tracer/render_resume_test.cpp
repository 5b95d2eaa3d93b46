// Stop and resume (issue 6), library level: a render continued from a checkpoint after k
// passes, or stopped by its stop flag after k passes and continued, ends with every
// accumulator equal bit for bit to an uninterrupted render of N passes, for the path,
// bidirectional and vcm integrators. The tool level is raytrace_resume_tool_test.cpp.
#include <atomic>
#include <cstring>

#include <gtest/gtest.h>

#include "converters/analytic/analytic_sources.h"
#include "converters/analytic/synth.h"
#include "core/error.h"
#include "lightmodel/model_build.h"
#include "lightmodel/model_file.h"
#include "support/test_support.h"
#include "tracer/film/checkpoint.h"
#include "tracer/render/renderer.h"
#include "tracer/scene_language/scene_language.h"
#include "tracer/tracer_support.h"

namespace rayset::tracer {
namespace {

// A Lambertian disk (1e5 rays; its light model stored as .vdb) hanging in a closed box of
// albedo 0.5 with a faint point light: primary and secondary light and direct visibility
// enter the render.
std::string bidirectional_box(const test::ScratchDir& dir) {
    const std::string rays = dir.file("disk.tm25ray"), model = dir.file("disk.vdb");
    test::write_disk_rays(rays, 100000);
    lightmodel::write_model(lightmodel::build_model(rays, {}), model);
    return test::disk_in_box_scene(model);
}

void expect_same_bits(const SampleGrid& a, const SampleGrid& b, const std::string& what) {
    ASSERT_EQ(a.nx(), b.nx()) << what;
    ASSERT_EQ(a.ny(), b.ny()) << what;
    EXPECT_EQ(a.samples(), b.samples()) << what;
    EXPECT_EQ(std::memcmp(a.sums().data(), b.sums().data(), a.sums().size() * sizeof(Rgb)), 0)
        << what << " sums";
    EXPECT_EQ(std::memcmp(a.photometric_squares().data(), b.photometric_squares().data(),
                          a.photometric_squares().size() * sizeof(double)),
              0)
        << what << " squares";
}

void expect_same_state(const RenderResult& a, const RenderResult& b) {
    EXPECT_EQ(a.passes, b.passes);
    EXPECT_EQ(a.rays, b.rays);
    EXPECT_EQ(a.photons, b.photons);
    EXPECT_EQ(a.photon_radius, b.photon_radius);  // exactly
    EXPECT_EQ(a.photon_bytes, b.photon_bytes);
    EXPECT_EQ(a.visible_point_bytes, b.visible_point_bytes);
    expect_same_bits(a.film, b.film, "image");
    ASSERT_EQ(a.receivers.size(), b.receivers.size());
    for (size_t i = 0; i < a.receivers.size(); ++i)
        expect_same_bits(a.receivers[i].irradiance, b.receivers[i].irradiance, "receiver");
    ASSERT_EQ(a.layers.size(), b.layers.size());
    for (size_t l = 0; l < a.layers.size(); ++l) {
        expect_same_bits(a.layers[l].film, b.layers[l].film, a.layers[l].name);
        for (size_t i = 0; i < a.layers[l].receivers.size(); ++i)
            expect_same_bits(a.layers[l].receivers[i].irradiance,
                             b.layers[l].receivers[i].irradiance, a.layers[l].name + " receiver");
    }
}

// Renders N passes at once, then k passes, through a checkpoint file, continued to N, and a
// render stopped by the stop flag after k passes continued to N: all three end alike.
RenderResult check_resume(const std::string& scene_text, RenderSettings settings, int k, int n,
                          const test::ScratchDir& dir) {
    const std::string scene_file = dir.file("scene.pov");
    test::write_file(scene_file, scene_text);
    const SceneDescription description = parse_scene_file(scene_file);
    const RenderScene scene(description);
    settings.passes = n;
    const RenderResult whole = render(scene, settings);
    EXPECT_EQ(whole.passes, n);

    RenderSettings first = settings;
    first.passes = k;
    const RenderResult part = render(scene, first);
    EXPECT_EQ(part.passes, k);
    // Not the same yet: the test would show nothing otherwise.
    EXPECT_NE(std::memcmp(part.film.sums().data(), whole.film.sums().data(),
                          part.film.sums().size() * sizeof(Rgb)),
              0);
    EXPECT_LT(part.rays, whole.rays);

    const CheckpointIdentity identity = checkpoint_identity(description, settings);
    write_checkpoint(dir.file("scene.checkpoint"), identity, part);
    RenderResult loaded = read_checkpoint(dir.file("scene.checkpoint"), identity,
                                          blank_render(description, settings));
    expect_same_state(loaded, part);
    EXPECT_EQ(loaded.seconds, part.seconds);
    const RenderResult resumed = render(scene, settings, std::move(loaded));
    expect_same_state(resumed, whole);

    std::atomic<bool> stop{false};
    RenderControl control;
    control.stop = &stop;
    control.after_pass = [&](const RenderResult& state) { stop = state.passes == k; };
    RenderResult stopped = render(scene, settings, {}, control);
    EXPECT_EQ(stopped.passes, k);
    expect_same_state(render(scene, settings, std::move(stopped)), whole);
    return whole;
}

double total_green(const SampleGrid& grid) {
    double sum = 0;
    for (const Rgb& s : grid.sums()) sum += s.green;
    return sum;
}

TEST(RenderResume, PathIntegratorContinuesBitForBit) {
    test::ScratchDir dir;
    RenderSettings settings;
    settings.width = 24, settings.height = 18, settings.seed = 11;
    const RenderResult r = check_resume(test::cornell_with_receiver(), settings, 2, 5, dir);
    EXPECT_GT(total_green(r.film), 0);
    EXPECT_GT(total_green(r.receivers.at(0).irradiance), 0);
}

TEST(RenderResume, BidirectionalIntegratorContinuesBitForBit) {
    test::ScratchDir dir;
    const std::string scene = bidirectional_box(dir);
    RenderSettings settings;
    settings.width = 24, settings.height = 18, settings.seed = 4, settings.photons_per_pass = 5000;
    const RenderResult r =
        check_resume(scene, settings, 1, 4, dir);  // after pass 1: the default radius is set
    check_resume(scene, settings, 3, 4, dir);
    // Every kind of light is in the accumulators compared.
    for (const RenderLayer& layer : r.layers) {
        EXPECT_GT(total_green(layer.film), 0) << layer.name;
        if (layer.name != "direct_visibility") {
            EXPECT_GT(total_green(layer.receivers.at(0).irradiance), 0) << layer.name;
        }
    }
    EXPECT_GT(r.photons, 0u);
}

TEST(RenderResume, VcmIntegratorContinuesBitForBit) {
    // Its gather radius is measured in pass 0: a continued render goes on from the radius the
    // checkpoint holds, and the threads do not change the image either.
    test::ScratchDir dir;
    std::string scene = bidirectional_box(dir);
    scene.replace(scene.find("\"bidirectional\""), 15, "\"vcm\"");
    RenderSettings settings;
    settings.width = 24, settings.height = 18, settings.seed = 4, settings.photons_per_pass = 5000;
    const RenderResult r = check_resume(scene, settings, 2, 4, dir);
    for (const RenderLayer& layer : r.layers) EXPECT_GT(total_green(layer.film), 0) << layer.name;
    EXPECT_GT(r.photons, 0u);
    RenderSettings one_thread = settings;
    one_thread.passes = 4, one_thread.threads = 1;
    const RenderScene parsed(parse_scene_text(scene, dir.file("scene.pov")));
    expect_same_state(render(parsed, one_thread), r);
}

TEST(RenderResume, ContinuedStateMustFitTheScene) {
    const RenderScene scene(parse_scene_text(test::cornell_with_receiver(), "cornell.pov"));
    RenderSettings settings;
    settings.width = 8, settings.height = 6, settings.passes = 1;
    RenderResult small = render(scene, settings);
    settings.width = 10, settings.passes = 2;
    EXPECT_THROW(render(scene, settings, std::move(small)), Error);
}

}  // namespace
}  // namespace rayset::tracer
