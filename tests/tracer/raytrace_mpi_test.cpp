// raytrace across processes: `mpirun -n 2 raytrace ...` renders the passes of one process's
// render, shared between the ranks, and ends with the same accumulators up to the order of
// their sums: every accumulator is a sum of P per-pass values >= 0, and any two orders of
// summing P such values differ by at most 2 (P - 1) u times their sum (u = 2^-53, to first
// order; Higham, "Accuracy and stability of numerical algorithms", 4.2). Two runs with two
// ranks give the same bits, and a render resumed under mpirun ends where the one-process
// render ends. Path and bidirectional integrators (the latter with the gather radius taken
// from the first pass, which the root renders alone and hands on).
#include <cfloat>
#include <cmath>
#include <cstdlib>

#include <gtest/gtest.h>

#include "converters/analytic/analytic_sources.h"
#include "converters/analytic/synth.h"
#include "support/test_support.h"
#include "tracer/film/checkpoint.h"
#include "tracer/render/renderer.h"
#include "tracer/scene_language/scene_language.h"
#include "tracer/tracer_support.h"

namespace rayset::tracer {
namespace {

const std::string kRaytrace = std::string(RAYSET_BINARY_DIR) + "/tracer/raytrace";
constexpr int kPasses = 7, kWidth = 40, kHeight = 30, kSeed = 5;

std::string cornell_with_receiver(const test::ScratchDir&) { return test::cornell_with_receiver(); }

// A Lambertian disk of 2e4 rays (its model built at load by every rank) in a closed grey box,
// with a faint point light: all three layers.
std::string bidirectional_box(const test::ScratchDir& dir) {
    const std::string rays = dir.file("disk.tm25ray");  // beside the scene, named relative to it
    test::write_disk_rays(rays, 20000);
    return test::disk_in_box_scene("disk.tm25ray");
}

// raytrace on `processes` processes (1: no mpirun) in `dir`, its state kept in out.checkpoint.
void raytrace(const test::ScratchDir& dir, int processes, const std::string& more = "") {
    std::string line = "cd '" + dir.path().string() + "' && ";
    if (processes > 1)
        line += "mpirun --allow-run-as-root --oversubscribe -n " + std::to_string(processes) + " ";
    line += "'" + kRaytrace + "' scene.pov +W" + std::to_string(kWidth) + " +H" +
            std::to_string(kHeight) + " -o out.exr --no-png --seed " + std::to_string(kSeed) +
            " --threads 1 -q --keep-checkpoint " + more;
    const test::CommandResult run = test::run_command(line + " 2>&1");
    ASSERT_EQ(run.status, 0) << line << "\n" << run.output;
}

RenderResult state(const test::ScratchDir& dir) {
    const SceneDescription description = parse_scene_file(dir.file("scene.pov"));
    RenderSettings settings;
    settings.width = kWidth, settings.height = kHeight, settings.seed = kSeed;
    return read_checkpoint(dir.file("out.checkpoint"), checkpoint_identity(description, settings),
                           blank_render(description, settings));
}

template <class F>
void for_each_grid_pair(const RenderResult& a, const RenderResult& b, F&& f) {
    f(a.film, b.film, "film");
    for (size_t r = 0; r < a.receivers.size(); ++r)
        f(a.receivers[r].irradiance, b.receivers[r].irradiance, "receiver");
    for (size_t l = 0; l < a.layers.size(); ++l) {
        f(a.layers[l].film, b.layers[l].film, a.layers[l].name);
        for (size_t r = 0; r < a.layers[l].receivers.size(); ++r)
            f(a.layers[l].receivers[r].irradiance, b.layers[l].receivers[r].irradiance,
              a.layers[l].name + " receiver");
    }
}

// Same passes, rays, photons and radius; every accumulator within `relative` of the other
// (0: the same bits). Returns the largest relative difference seen.
double compare(const RenderResult& a, const RenderResult& b, double relative) {
    EXPECT_EQ(a.passes, b.passes);
    EXPECT_EQ(a.rays, b.rays);
    EXPECT_EQ(a.photons, b.photons);
    EXPECT_EQ(a.photon_radius, b.photon_radius);
    EXPECT_EQ(a.layers.size(), b.layers.size());
    EXPECT_EQ(a.receivers.size(), b.receivers.size());
    double largest = 0;
    auto close = [&](double x, double y, const std::string& what) {
        EXPECT_LE(std::abs(x - y), relative * std::abs(x)) << what << ": " << x << " and " << y;
        if (x != 0) largest = std::max(largest, std::abs(x - y) / std::abs(x));
    };
    for_each_grid_pair(a, b,
                       [&](const SampleGrid& g, const SampleGrid& h, const std::string& what) {
                           ASSERT_EQ(g.sums().size(), h.sums().size()) << what;
                           EXPECT_EQ(g.samples(), h.samples()) << what;
                           for (size_t i = 0; i < g.sums().size(); ++i) {
                               close(g.sums()[i].red, h.sums()[i].red, what);
                               close(g.sums()[i].green, h.sums()[i].green, what);
                               close(g.sums()[i].blue, h.sums()[i].blue, what);
                               close(g.photometric_squares()[i], h.photometric_squares()[i], what);
                           }
                       });
    return largest;
}

void expect_two_ranks_render_as_one(std::string (*scene)(const test::ScratchDir&)) {
    test::ScratchDir one, two, again, resumed;
    for (const test::ScratchDir* dir : {&one, &two, &again, &resumed})
        test::write_file(dir->file("scene.pov"), scene(*dir));
    const std::string passes = "--passes " + std::to_string(kPasses);
    raytrace(one, 1, passes);
    raytrace(two, 2, passes);
    raytrace(again, 2, passes);
    raytrace(resumed, 2, "--passes 3");
    raytrace(resumed, 2, passes + " --resume");
    if (::testing::Test::HasFatalFailure()) return;

    const RenderResult single = state(one);
    ASSERT_EQ(single.passes, kPasses);
    const double bound = 2 * (kPasses - 1) * DBL_EPSILON / 2 * (1 + 1e-6);
    const double largest = compare(single, state(two), bound);
    compare(state(two), state(again), 0);
    const double largest_resumed = compare(single, state(resumed), bound);
    std::printf(
        "%s: 2 ranks against 1 process, largest relative difference %.3g (resumed %.3g), bound "
        "%.3g\n",
        single.layers.empty() ? "path" : "bidirectional", largest, largest_resumed, bound);
}

TEST(RaytraceMpi, TwoRanksRenderThePathTracersPassesOfOneProcess) {
    expect_two_ranks_render_as_one(cornell_with_receiver);
}

TEST(RaytraceMpi, TwoRanksRenderTheBidirectionalPassesOfOneProcess) {
    expect_two_ranks_render_as_one(bidirectional_box);
}

}  // namespace
}  // namespace rayset::tracer
