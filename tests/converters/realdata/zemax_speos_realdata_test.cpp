// Real Zemax and SPEOS files. The truth is test_08_rayfile_reference_results.json, the values
// ansys/optical-automation (MIT) decodes from its test files: each of its three arrays is
// [luminous lm, radiant W, ray count, then per ray x y z l m n wavelength(um) flux].
// "ray_content" is test_08_ray.ray (SPEOS), "dat_content" test_08_dat.DAT (Zemax flux only),
// "sdf_content" test_08_sdf.sdf (Zemax spectral); the *_reference files are that project's
// conversions of them and hold the same rays.
#include "converters/colour/spectrum.h"
#include "converters/formats/codecs.h"
#include "converters/rays/io.h"
#include "support/test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <map>

namespace rayset {
namespace {

std::string rayfile(const std::string& name) { return test::shared_data("rayfiles/" + name); }

struct ReferenceRay {
    Vec3f origin, direction;
    double um, flux;
};
struct Reference {
    double luminous, radiant;
    uint64_t count;
    std::vector<ReferenceRay> rays;
};

Reference reference(const std::string& key) {
    const auto json =
        nlohmann::json::parse(test::read_file(rayfile("test_08_rayfile_reference_results.json")));
    const auto& a = json.at(key);
    Reference r{a.at(0).get<double>(), a.at(1).get<double>(), a.at(2).get<uint64_t>(), {}};
    for (size_t i = 3; i + 8 <= a.size(); i += 8) {
        auto f = [&](size_t k) { return a.at(i + k).get<double>(); };
        r.rays.push_back({{float(f(0)), float(f(1)), float(f(2))},
                          {float(f(3)), float(f(4)), float(f(5))},
                          f(6),
                          f(7)});
    }
    return r;
}

std::vector<Ray> read_all(RayDecoder& decoder) {
    std::vector<Ray> rays;
    RayChunk chunk;
    while (decoder.read(chunk, 4)) rays.insert(rays.end(), chunk.rays.begin(), chunk.rays.end());
    return rays;
}

std::vector<Ray> read_all(RayReader& reader) {
    std::vector<Ray> rays;
    RayChunk chunk;
    while (reader.read(chunk)) rays.insert(rays.end(), chunk.rays.begin(), chunk.rays.end());
    return rays;
}

// Positions and directions are f32 in both, so they must be equal; wavelengths go through the
// um <-> nm conversion (one float rounding: 1e-6 relative); `nm` is the wavelength of rays
// that carry none of their own (Zemax flux-only files).
void expect_rays(const std::vector<Ray>& rays, const Reference& ref, bool luminous = false,
                 float nm = kUnknown) {
    ASSERT_EQ(rays.size(), ref.count);
    ASSERT_EQ(ref.rays.size(), ref.count);
    for (size_t i = 0; i < rays.size(); ++i) {
        SCOPED_TRACE("ray " + std::to_string(i + 1));
        EXPECT_EQ(rays[i].origin, ref.rays[i].origin);
        EXPECT_EQ(rays[i].direction, ref.rays[i].direction);
        EXPECT_EQ(luminous ? rays[i].luminous : rays[i].radiant, float(ref.rays[i].flux));
        const double got = std::isnan(nm) ? rays[i].wavelength : nm;
        EXPECT_NEAR(got, ref.rays[i].um * 1000, 1e-6 * ref.rays[i].um * 1000);
    }
}

// optical-automation used 683 lm/W, rayset 683.002 (2.9e-6 relative), and its figure is rounded
// to 1e-3 lm (1.5e-6 at 680 lm): 5e-6 covers both and nothing more.
constexpr double kLuminousConvention = 5e-6;

TEST(SpeosRealData, ThreeFilesDecodeToTheReferenceValues) {
    RAYSET_REQUIRE_SHARED_DATA();
    const std::pair<const char*, const char*> files[] = {
        {"test_08_ray.ray", "ray_content"},
        {"test_08_dat_reference.ray", "dat_content"},
        {"test_08_sdf_reference.ray", "sdf_content"}};
    for (const auto& [name, key] : files) {
        SCOPED_TRACE(name);
        const Reference ref = reference(key);
        auto decoder = open_speos(rayfile(name));
        const RayHeader& h = decoder->header();
        EXPECT_EQ(h.ray_count, 11u);
        EXPECT_EQ(h.ray_count, ref.count);
        EXPECT_EQ(float(h.stated_radiant), float(ref.radiant));
        EXPECT_EQ(float(h.stated_luminous), float(ref.luminous));
        EXPECT_EQ(h.spectral, SpectralKind::per_ray_wavelength);
        expect_rays(read_all(*decoder), ref);
    }
}

TEST(ZemaxRealData, FluxOnlyDatDecodesToTheReferenceValues) {
    RAYSET_REQUIRE_SHARED_DATA();
    const Reference ref = reference("dat_content");
    auto decoder = open_zemax_binary(rayfile("test_08_dat.DAT"));
    const RayHeader& h = decoder->header();
    EXPECT_EQ(h.ray_count, ref.count);
    EXPECT_EQ(h.stated_radiant, ref.radiant);
    EXPECT_EQ(h.ray_set_flux, 1.0);
    EXPECT_EQ(h.unit, LengthUnit::mm);
    EXPECT_EQ(h.description, "Converted from SPEOS .ray file.");
    EXPECT_EQ(h.placement.scale, (Vec3f{0, 0, 0}));  // as written, though "unused"
    ASSERT_EQ(h.spectral, SpectralKind::single_wavelength);
    expect_rays(read_all(*decoder), ref, false, h.single_wavelength);
    // The reference's luminous figure is 1 W at the header's 550 nm through V(lambda).
    const double lm =
        kMaxLuminousEfficacy * photopic_efficiency(h.single_wavelength) * h.stated_radiant;
    EXPECT_NEAR(lm, ref.luminous, kLuminousConvention * ref.luminous);
}

// The data README warns that flux and wavelength look swapped in this file (1 um and
// 0.486..0.656 W); it is read as written, and the reference decodes it the same way.
TEST(ZemaxRealData, SpectralSdfFilesDecodeToTheReferenceValues) {
    RAYSET_REQUIRE_SHARED_DATA();
    const std::pair<const char*, const char*> files[] = {
        {"test_08_sdf.sdf", "sdf_content"}, {"test_08_ray_reference.sdf", "ray_content"}};
    for (const auto& [name, key] : files) {
        SCOPED_TRACE(name);
        const Reference ref = reference(key);
        auto decoder = open_zemax_binary(rayfile(name));
        const RayHeader& h = decoder->header();
        EXPECT_EQ(h.ray_count, ref.count);
        EXPECT_EQ(h.stated_radiant, ref.radiant);
        EXPECT_EQ(h.spectral, SpectralKind::per_ray_wavelength);
        EXPECT_EQ(h.unit, LengthUnit::mm);
        expect_rays(read_all(*decoder), ref);
    }
    // sdf_content's luminous 0: every ray at 1000 nm, where V is 0.
    EXPECT_EQ(reference("sdf_content").luminous, 0.0);
    EXPECT_EQ(photopic_efficiency(1000), 0.0);
}

// One ray in lumens whose flux equals the source flux, so the reader keeps it unscaled.
TEST(ZemaxRealData, LumensFileHoldsOneRayOfTheSourceFlux) {
    RAYSET_REQUIRE_SHARED_DATA();
    const std::string path = rayfile("test_08_dat_flux_type_1.dat");
    auto decoder = open_zemax_binary(path);
    const RayHeader& h = decoder->header();
    EXPECT_EQ(h.ray_count, 1u);
    EXPECT_TRUE(h.has_luminous);
    EXPECT_FALSE(h.has_radiant);
    EXPECT_EQ(h.stated_luminous, double(0.0015f));
    EXPECT_EQ(h.ray_set_flux, 1.0);
    EXPECT_EQ(h.description, "Flux_type=1 for Unitest.");
    const auto rays = read_all(*decoder);
    ASSERT_EQ(rays.size(), 1u);
    EXPECT_EQ(rays[0].origin, (Vec3f{1, 1, 1}));
    EXPECT_EQ(rays[0].direction, (Vec3f{0, 0, 1}));
    EXPECT_EQ(rays[0].luminous, 0.0015f);
    auto reader = open_rays(path);
    read_all(*reader);
    EXPECT_EQ(reader->luminous_scale(), 1.0);
    EXPECT_EQ(float(reader->totals().luminous), 0.0015f);
}

// TM25RaySetTools wrote the same three rays as LightTools binary (nm) and as Zemax (um): a
// second decoder of a second file is the truth for this one.
TEST(ZemaxRealData, ThreeRayZemaxFileMatchesItsLightToolsTwin) {
    RAYSET_REQUIRE_SHARED_DATA();
    auto zemax = open_zemax_binary(rayfile("RayFileConverter_ThreeRays_Wavelength_ZMX.ray"));
    auto lighttools =
        open_lighttools_binary(rayfile("RayFileConverter_ThreeRays_Wavelength.1.ray"));
    const RayHeader& h = zemax->header();
    EXPECT_EQ(h.description, "LT ray file");
    EXPECT_EQ(h.unit, LengthUnit::mm);
    EXPECT_EQ(h.ray_count, 3u);
    EXPECT_EQ(h.spectral,
              SpectralKind::per_ray_wavelength);  // the header's NaN wavelength is ignored
    EXPECT_EQ(h.stated_radiant, lighttools->header().stated_radiant);
    EXPECT_EQ(h.placement.scale, (Vec3f{1, 1, 1}));
    const auto z = read_all(*zemax), l = read_all(*lighttools);
    ASSERT_EQ(z.size(), l.size());
    for (size_t i = 0; i < z.size(); ++i) {
        EXPECT_EQ(z[i].origin, l[i].origin);
        EXPECT_EQ(z[i].direction, l[i].direction);
        EXPECT_EQ(z[i].radiant, l[i].radiant);
        EXPECT_NEAR(z[i].wavelength, l[i].wavelength, 1e-6 * l[i].wavelength);
    }
    EXPECT_EQ(l[1].wavelength, 450.0f);
}

// The two hand-made text files share their first seven columns; the second adds wavelengths
// 510..580 and 450 nm in um, and states unit code 2 (cm) where the first states 4 (mm).
TEST(ZemaxRealData, TextFilesReadWithTheirValues) {
    RAYSET_REQUIRE_SHARED_DATA();
    auto plain = open_rays(rayfile("TestRayFiles_ZemaxText.txt"));
    auto spectral = open_rays(rayfile("TestRayFiles_ZemaxWavelengthText.txt"));
    EXPECT_EQ(plain->file_header().format, RayFormat::zemax_text);
    EXPECT_EQ(plain->file_header().unit, LengthUnit::mm);
    EXPECT_EQ(plain->file_header().spectral, SpectralKind::none);
    EXPECT_EQ(spectral->file_header().format, RayFormat::zemax_text);
    EXPECT_EQ(spectral->file_header().unit, LengthUnit::cm);
    EXPECT_EQ(spectral->file_header().spectral, SpectralKind::per_ray_wavelength);
    const auto p = read_all(*plain), s = read_all(*spectral);
    ASSERT_EQ(p.size(), 9u);
    ASSERT_EQ(s.size(), 9u);
    EXPECT_EQ(p[0].origin, (Vec3f{-0.118104f, -5.434330f, 0}));
    EXPECT_EQ(p[0].direction, (Vec3f{0.543849f, -0.116945f, 0.830994f}));
    EXPECT_EQ(p[8].radiant, 2.968579f);
    const float nm[9] = {510, 520, 530, 540, 550, 560, 570, 580, 450};
    double sum = 0;
    for (size_t i = 0; i < 9; ++i) {
        EXPECT_EQ(s[i].origin, p[i].origin);
        EXPECT_EQ(s[i].direction, p[i].direction);
        EXPECT_EQ(s[i].radiant, p[i].radiant);
        EXPECT_NEAR(s[i].wavelength, nm[i], 1e-6 * nm[i]);
        sum += p[i].radiant;
    }
    // The file states no total, so the rays keep their own: the sum of the printed fluxes.
    EXPECT_NEAR(sum,
                45.576770 + 12.103610 + 7.263157 + 4.487494 + 3.219967 + 12.181310 + 1.790850 +
                    49.274200 + 2.968579,
                1e-5);
    EXPECT_EQ(plain->radiant_scale(), 1.0);
}

// Every file in the folder: each of these sniffers claims exactly its own files.
TEST(ZemaxSpeosRealData, SniffersClaimOnlyTheirOwnFiles) {
    RAYSET_REQUIRE_SHARED_DATA();
    const std::map<std::string, RayFormat> own = {
        {"test_08_ray.ray", RayFormat::speos},
        {"test_08_dat_reference.ray", RayFormat::speos},
        {"test_08_sdf_reference.ray", RayFormat::speos},
        {"test_08_dat.DAT", RayFormat::zemax_binary},
        {"test_08_dat_flux_type_1.dat", RayFormat::zemax_binary},
        {"test_08_sdf.sdf", RayFormat::zemax_binary},
        {"test_08_ray_reference.sdf", RayFormat::zemax_binary},
        {"RayFileConverter_ThreeRays_Wavelength_ZMX.ray", RayFormat::zemax_binary},
        {"TestRayFiles_ZemaxText.txt", RayFormat::zemax_text},
        {"TestRayFiles_ZemaxWavelengthText.txt", RayFormat::zemax_text},
    };
    size_t files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(test::shared_data("rayfiles"))) {
        const std::string name = entry.path().filename().string(), path = entry.path().string();
        SCOPED_TRACE(name);
        const Head head = read_head(path, 4096);
        const uint64_t size = file_size(path);
        const auto it = own.find(name);
        const bool mine = it != own.end();
        EXPECT_EQ(sniff_speos(head, size), mine && it->second == RayFormat::speos);
        EXPECT_EQ(sniff_zemax_binary(head, size), mine && it->second == RayFormat::zemax_binary);
        EXPECT_EQ(sniff_zemax_text(head, size), mine && it->second == RayFormat::zemax_text);
        if (mine) {
            EXPECT_EQ(detect_ray_format(path), it->second);
        }
        ++files;
    }
    EXPECT_GT(files, own.size());
}

}  // namespace
}  // namespace rayset
