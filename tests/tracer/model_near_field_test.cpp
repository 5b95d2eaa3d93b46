// The near field of an asymmetric source through the light model: a Lambertian disk (radius
// 1 mm, 1 W, 555 nm) tilted 30 degrees from the lattice's z axis, written by the synthesiser at
// 10^5 and 10^6 rays, built into a model with the default options and rendered onto illuminance
// receivers by the bidirectional integrator. Receivers: 5 x 5 cells on the planes z = 2 mm and
// z = 10 mm (1 and 5 source sizes above the disk's centre), each 2 z wide, facing the disk.
// Truth: the disk's closed-form irradiance at the cells' centres, where receivers measure.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "converters/analytic/analytic_sources.h"
#include "converters/analytic/synth.h"
#include "lightmodel/model_build.h"
#include "lightmodel/model_file.h"
#include "support/test_support.h"
#include "tracer/render/renderer.h"
#include "tracer/scene_language/scene_language.h"

namespace rayset::tracer {
namespace {

constexpr double kTiltDeg = 30;
constexpr int kCells = 5;

const analytic::LambertianDisk& tilted_disk() {
    static const analytic::LambertianDisk disk = [] {
        analytic::Spectrum spectrum;
        spectrum.wavelength_nm = 555;
        return analytic::LambertianDisk::with_flux(1, 1, spectrum, kTiltDeg);
    }();
    return disk;
}

struct NearFieldError {
    double rms[2] = {0, 0};  // per plane: relative RMS over its cells
    double worst_se = 0;     // the receivers' largest relative standard error
};

NearFieldError near_field_error(uint64_t rays, uint64_t seed,
                                const lightmodel::ModelOptions& options = {}) {
    test::ScratchDir scratch;
    const std::string ray_file = scratch.file("tilted.tm25ray"), model = scratch.file("tilted.vdb");
    {
        auto out = create_rays(ray_file, RayFormat::tm25, synth_header(tilted_disk(), rays, seed));
        synthesize(tilted_disk(), rays, seed, *out);
    }
    lightmodel::write_model(lightmodel::build_model(ray_file, options), model);

    const double heights[2] = {2, 10};
    std::string scene = R"(global_settings { integrator "bidirectional" }
        ray_source { ")" +
                        model + "\" }\n";
    for (double z : heights) {
        char receiver[256];
        std::snprintf(
            receiver, sizeof receiver,
            "illuminance_receiver { <%g, %g, %g>, <0, %g, 0>, <%g, 0, 0> resolution <%d, %d> }\n",
            -z, -z, z, 2 * z, 2 * z, kCells, kCells);
        scene += receiver;
    }
    RenderSettings settings;
    // Nothing reflects: photons only cost time; a pass takes 2600 samples per receiver cell.
    settings.render_image = false, settings.passes = 64, settings.seed = 11,
    settings.photons_per_pass = 1 << 17;
    const RenderResult r =
        render(RenderScene(parse_scene_text(scene, scratch.file("scene.pov"))), settings);

    NearFieldError error;
    for (int plane = 0; plane < 2; ++plane) {
        const ReceiverMap& map = r.layers[1].receivers.at(size_t(plane));
        double sum_squares = 0;
        for (int j = 0; j < map.irradiance.ny(); ++j)
            for (int i = 0; i < map.irradiance.nx(); ++i) {
                const double truth =
                    1e6 * tilted_disk().irradiance(map.cell_centre(i, j), {0, 0, -1});  // W/m^2
                const double measured = luminance_weight(map.irradiance.mean(i, j));
                const double se = map.irradiance.photometric_standard_error(i, j) / kLumensPerWatt;
                sum_squares += std::pow(measured / truth - 1, 2);
                error.worst_se = std::max(error.worst_se, se / truth);
            }
        error.rms[plane] = std::sqrt(sum_squares / (kCells * kCells));
    }
    std::printf(
        "[ figures  ] tilted disk, %8llu rays, diagram smoothing %s: illuminance RMS %.4f at 1 "
        "source size, "
        "%.4f at 5; receivers' largest standard error %.4f\n",
        (unsigned long long)rays, lightmodel::diagram_smoothing_name(options.diagram_smoothing),
        error.rms[0], error.rms[1], error.worst_se);
    return error;
}

// Bounds: 1% RMS at 1e6 rays and 2% at 1e5, with the default (smoothed) diagrams; at 1e5 rays
// the histograms of 40 x 12 cells do worse on the same rays. At 1e5 rays the error is mostly the
// far field's noise: over seeds 23 to 27 it is 1.1% to 2.3% at 5 source sizes (mean 1.7%). The
// receivers' noise (largest standard error printed) is kept below a fifth of the bound, so the RMS
// measures the model.
TEST(ModelNearField, TiltedDiskAtOneAndFiveSourceSizes) {
    NearFieldError e;
    for (const auto& [rays, bound] : {std::pair<uint64_t, double>{1000000, 0.01}, {100000, 0.02}}) {
        e = near_field_error(rays, 23);
        EXPECT_LT(e.worst_se, bound / 5) << rays;
        EXPECT_LT(e.rms[0], bound) << rays << " rays, 1 source size";
        EXPECT_LT(e.rms[1], bound) << rays << " rays, 5 source sizes";
    }
    lightmodel::ModelOptions histogram;
    histogram.diagram_smoothing = lightmodel::DiagramSmoothing::none;
    const NearFieldError binned = near_field_error(100000, 23, histogram);
    EXPECT_GT(binned.rms[1], 0.02);
    for (int plane = 0; plane < 2; ++plane) EXPECT_LT(e.rms[plane], binned.rms[plane]) << plane;
}

}  // namespace
}  // namespace rayset::tracer
