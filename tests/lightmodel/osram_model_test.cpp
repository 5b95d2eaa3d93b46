// The model of a real measured file: OSRAM's blue OSTAR Stage chip (100k rays, TM-25, 1.68 W).
// It builds, keeps the file's flux, and its far field agrees with the rays' own far field in the
// same cells within the rays' statistics; the figures the issue asks for are printed.
#include "converters/photometry/farfield.h"
#include "converters/rays/ray_stream.h"
#include "lightmodel/complex_source.h"
#include "lightmodel/model_build.h"
#include "lightmodel/model_file.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

namespace rayset::test {
namespace {

TEST(OsramModel, BuildsKeepsItsFluxAndFarField) {
    RAYSET_REQUIRE_SHARED_DATA();
    const std::string file =
        shared_data("rayfiles/rayfile_LERTDUW_S2WP_blue_100k_20161013_IES_TM25.TM25RAY");
    ScratchDir dir;
    auto model = std::make_shared<lightmodel::LightModel>(lightmodel::build_model(file, {}));
    lightmodel::write_model(*model, dir.file("blue.vdb"));
    const lightmodel::ComplexSource source(model);

    auto reader = open_rays(file);
    const double stated = reader->file_header().stated_radiant;
    EXPECT_NEAR(source.phi() / stated, 1, 1e-6);

    // The rays' far field in 10 x 10 degree cells (about 400 rays per lit cell), radiometric.
    FarFieldOptions options;
    options.c_step_deg = 10;
    options.gamma_step_deg = 10;
    options.quantity = FarFieldQuantity::radiometric;
    const FarField rays = far_field(*reader, options);
    const FarFieldGrid grid(options);
    const size_t planes = rays.photometry.horizontal_deg.size();  // 0..360, 360 repeats 0
    // Mean intensity of the model over each cell: 8 x 8 directions uniform in solid angle.
    double chi2 = 0;
    int cells = 0, beyond = 0;
    for (size_t j = 0; j < grid.gamma_count(); ++j)
        for (size_t i = 0; i + 1 < planes; ++i) {
            const size_t k = i * grid.gamma_count() + j;
            if (rays.variance[k] <= 0 || rays.flux[k] / rays.total_flux < 1e-3) continue;
            const double c0 = (i * 10.0 - 5) * kPi / 180,
                         g0 = std::cos(grid.gamma_low(j) * kPi / 180),
                         g1 = std::cos(grid.gamma_high(j) * kPi / 180);
            double mean = 0;
            for (int a = 0; a < 8; ++a)
                for (int b = 0; b < 8; ++b) {
                    const double u = g0 + (g1 - g0) * (a + 0.5) / 8,
                                 c = c0 + 10 * kPi / 180 * (b + 0.5) / 8;
                    const double s = std::sqrt(std::max(0.0, 1 - u * u));
                    mean += source.intensity({s * std::cos(c), s * std::sin(c), u}) / 64;
                }
            const double candela = rays.photometry.candela[k];
            const double z = (mean - candela) / std::sqrt(rays.variance[k]);
            chi2 += z * z;
            beyond += std::abs(z) > 4;
            ++cells;
        }
    std::printf(
        "[ figures  ] OSRAM blue: %llu rays, %zu spheres, %zu flux cells, %zu diagrams; model %ju "
        "bytes, ray "
        "file %ju bytes (%.1f%%); far field: %d cells, chi-square/cells %.2f, %d beyond 4 sigma\n",
        (unsigned long long)model->source.rays, model->spheres.size(), model->flux_cells.size(),
        model->diagrams.size(), (uintmax_t)std::filesystem::file_size(dir.file("blue.vdb")),
        (uintmax_t)std::filesystem::file_size(file),
        100.0 * double(std::filesystem::file_size(dir.file("blue.vdb"))) /
            double(std::filesystem::file_size(file)),
        cells, chi2 / cells, beyond);
    // The model's diagrams are made of the same rays, so the model cannot be further from them
    // than their own noise unless it distorts them: chi-square per cell below 1 on average
    // (an independent estimate would give 2), and no cell beyond 4 standard deviations.
    EXPECT_GT(cells, 100);
    EXPECT_LT(chi2 / cells, 1.0);
    EXPECT_EQ(beyond, 0);
}

}  // namespace
}  // namespace rayset::test
