// Every real ray file converted to every ray format and read back: each field that both the
// source and the target format hold comes back unchanged, bit for bit where both store f32.
// Where a target cannot hold what a file is (e.g. SPEOS needs radiant flux and a wavelength,
// which a luminous-only file lacks), the writer must refuse with a message saying so; the test
// prints those pairs, and checks that every file converts to the formats that can hold it.
#include <gtest/gtest.h>

#include "converters/rays/ray_stream.h"
#include "support/test_support.h"

#include <cmath>
#include <cstring>
#include <filesystem>
#include <vector>

namespace {

using namespace rayset;

struct Rays {
    RayHeader header;
    std::vector<Ray> rays;
};

Rays read_all(const std::string& path, RayReadOptions options = {}) {
    auto reader = open_rays(path, options);
    Rays out;
    out.header = reader->header();
    RayChunk chunk;
    while (reader->read(chunk))
        out.rays.insert(out.rays.end(), chunk.rays.begin(), chunk.rays.end());
    return out;
}

bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

const char* kFiles[] = {
    "rayfiles/rayfile_LERTDUW_S2WP_blue_100k_20161013_IES_TM25.TM25RAY",
    "rayfiles/Cyl10k.1.tm25ray",
    "rayfiles/Cyl1M_Faberge.1.tm25ray",
    "rayfiles/CreatePointSourceRayFile_farfield.TM25ray",
    "rayfiles/Cyl10k.1.ray",
    "rayfiles/RayFileConverter_ThreeRays_PowerOnly.1.ray",
    "rayfiles/RayFileConverter_ThreeRays_Wavelength.1.ray",
    "rayfiles/RayFileConverter_ThreeRays_Wavelength.1.txt",
    "rayfiles/RayFileConverter_ThreeRays_Wavelength_ZMX.ray",
    "rayfiles/TestRayFiles_ZemaxText.txt",
    "rayfiles/TestRayFiles_ZemaxWavelengthText.txt",
    "rayfiles/test_08_dat.DAT",
    "rayfiles/test_08_dat_flux_type_1.dat",
    "rayfiles/test_08_sdf.sdf",
    "rayfiles/test_08_ray_reference.sdf",
    "rayfiles/test_08_ray.ray",
    "rayfiles/test_08_dat_reference.ray",
    "rayfiles/test_08_sdf_reference.ray",
};

const RayFormat kTargets[] = {
    RayFormat::tm25,         RayFormat::lighttools_binary, RayFormat::lighttools_text,
    RayFormat::zemax_binary, RayFormat::zemax_text,        RayFormat::speos,
    RayFormat::csv};

// Formats storing wavelength in micrometres round it once each way.
bool wavelength_in_um(RayFormat f) {
    return f == RayFormat::zemax_binary || f == RayFormat::zemax_text;
}

// Compares what both headers say the rays carry; `via` is the format the rays went through.
void expect_same_fields(const Rays& original, const Rays& back, RayFormat via) {
    const double to_mm = millimetres_per(original.header.unit);
    EXPECT_EQ(back.rays.size(), original.rays.size());
    const double back_to_mm = millimetres_per(back.header.unit);
    const bool same_unit = back.header.unit == original.header.unit;
    const bool radiant = original.header.has_radiant && back.header.has_radiant;
    const bool luminous = original.header.has_luminous && back.header.has_luminous;
    const bool lossy_wavelength = wavelength_in_um(via) || wavelength_in_um(original.header.format);
    for (size_t i = 0; i < original.rays.size(); ++i) {
        const Ray& a = original.rays[i];
        const Ray& b = back.rays[i];
        if (same_unit) {
            EXPECT_TRUE(same_bits(a.origin.x, b.origin.x) && same_bits(a.origin.y, b.origin.y) &&
                        same_bits(a.origin.z, b.origin.z))
                << "ray " << i;
        } else {  // converted to the target's unit: one f32 rounding
            const float* pa = &a.origin.x;
            const float* pb = &b.origin.x;
            for (int k = 0; k < 3; ++k)
                EXPECT_NEAR(pb[k] * back_to_mm, pa[k] * to_mm,
                            1e-6 * std::abs(pa[k] * to_mm) + 1e-12)
                    << "ray " << i;
        }
        EXPECT_TRUE(same_bits(a.direction.x, b.direction.x) &&
                    same_bits(a.direction.y, b.direction.y) &&
                    same_bits(a.direction.z, b.direction.z))
            << "ray " << i;
        if (radiant) {
            EXPECT_TRUE(same_bits(a.radiant, b.radiant))
                << "ray " << i << ": " << a.radiant << " vs " << b.radiant;
        }
        if (luminous) {
            EXPECT_TRUE(same_bits(a.luminous, b.luminous))
                << "ray " << i << ": " << a.luminous << " vs " << b.luminous;
        }
        const float wa = original.header.spectral == SpectralKind::single_wavelength
                             ? original.header.single_wavelength
                             : a.wavelength;
        const float wb = back.header.spectral == SpectralKind::single_wavelength
                             ? back.header.single_wavelength
                             : b.wavelength;
        if (!std::isnan(wa) && !std::isnan(wb)) {
            if (lossy_wavelength) {
                EXPECT_NEAR(wb, wa, 1e-6 * wa) << "ray " << i;
            } else {
                EXPECT_TRUE(same_bits(wa, wb)) << "ray " << i << ": " << wa << " vs " << wb;
            }
        }
        if (::testing::Test::HasFailure()) return;  // the first differing ray says enough
    }
}

TEST(ConversionMatrix, EveryFileToEveryFormatKeepsWhatBothHold) {
    RAYSET_REQUIRE_SHARED_DATA();
    test::ScratchDir dir;
    int converted = 0, refused = 0;
    for (const char* name : kFiles) {
        const std::string path = test::shared_data(name);
        // Read as each format defines it; for TM-25 that keeps the rays as they are.
        const Rays original = read_all(path);
        for (RayFormat target : kTargets) {
            SCOPED_TRACE(std::string(name) + " -> " + to_string(target));
            const std::string out = dir.file("converted");
            try {
                auto reader = open_rays(path);
                auto writer = create_rays(out, target, reader->header());
                copy_rays(*reader, *writer);
            } catch (const Error& e) {
                // A refusal must say what the target cannot hold, and leave nothing behind.
                ++refused;
                std::printf("refused: %s -> %s: %s\n", name, to_string(target), e.what());
                EXPECT_FALSE(std::filesystem::exists(out));
                continue;
            }
            ++converted;
            // There, and back into the source's own format.
            const std::string again = dir.file("again");
            {
                auto reader = open_rays(out);
                auto writer = create_rays(again, original.header.format, reader->header());
                copy_rays(*reader, *writer);
            }
            expect_same_fields(original, read_all(out), target);
            expect_same_fields(original, read_all(again), target);
            std::filesystem::remove(again);
            std::filesystem::remove(out);
        }
    }
    std::printf("%d conversions checked, %d refused\n", converted, refused);
    // Every file reaches the formats that can hold any ray: TM-25, CSV and LightTools.
    EXPECT_GE(converted, int(std::size(kFiles)) * 3);
}

}  // namespace
