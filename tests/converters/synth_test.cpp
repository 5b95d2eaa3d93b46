// The random generator, building sources from text, and synthesising ray files.
#include "converters/analytic/synth.h"

#include "converters/colour/spectrum.h"
#include "converters/rays/io.h"
#include "core/random.h"
#include "support/test_support.h"
#include "synth_test_support.h"

#include <gtest/gtest.h>

#include <cstring>
#include <map>

namespace rayset {
namespace {

using test::MemoryEncoder;

TEST(Pcg32, MatchesTheReferenceImplementation) {
    // pcg32_srandom_r(&rng, 42, 54) in O'Neill's pcg32-demo (pcg-random.org) prints these.
    Pcg32 rng(42, 54);
    for (uint32_t expected :
         {0xa15c02b7u, 0x7b47f409u, 0xba1d3330u, 0x83d2f293u, 0xbfa4784bu, 0xcbed606eu})
        EXPECT_EQ(rng.next_u32(), expected);
}

TEST(Pcg32, UniformVariatesAreExactFractionsInTheUnitInterval) {
    Pcg32 a(5), b(5);
    double sum = 0;
    const int n = 1000000;
    for (int i = 0; i < n; ++i) {
        // The double is built from two raw words, the float from one: checked bit for bit.
        const uint64_t high = b.next_u32() >> 5, low = b.next_u32() >> 6;
        const double u = a.uniform();
        ASSERT_EQ(u, double((high << 26) | low) / 9007199254740992.0);
        ASSERT_GE(u, 0.0);
        ASSERT_LT(u, 1.0);
        sum += u;
    }
    // Mean of n uniforms: standard error 1/sqrt(12 n); 5 standard errors (two-sided 6e-7).
    EXPECT_NEAR(sum / n, 0.5, 5 / std::sqrt(12.0 * n));
    Pcg32 c(9);
    int seen[7] = {0};
    for (int i = 0; i < 70000; ++i) {
        const uint32_t k = c.below(7);
        ASSERT_LT(k, 7u);
        ++seen[k];
    }
    // Each count ~ Binomial(70000, 1/7): 10000 +- 5.5 sigma (sigma = 90.6).
    for (int count : seen) EXPECT_NEAR(count, 10000, 500);
    EXPECT_NE(Pcg32(1).next_u32(), Pcg32(2).next_u32());
    EXPECT_NE(Pcg32(1, 0).next_u32(), Pcg32(1, 1).next_u32());
}

// ---------------------------------------------------------------------------------------------

std::string error_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    return "no error";
}

TEST(SynthSources, BuildFromNameAndParameters) {
    auto disk = make_source(
        "disk", parse_source_parameters({"radius=2", "tilt=60", "flux=3", "wavelength=450"}));
    EXPECT_EQ(disk->name(), "disk");
    EXPECT_DOUBLE_EQ(disk->total_flux(), 3.0);
    // I0 = flux / pi for Lambert, along the normal (sin 60, 0, cos 60); half of it along z.
    EXPECT_DOUBLE_EQ(disk->intensity({std::sqrt(0.75), 0, 0.5}), 3.0 / kPi);
    EXPECT_NEAR(disk->intensity({0, 0, 1}), 1.5 / kPi, 1e-15);
    // parameters() reads back to the same source.
    std::vector<std::string> words;
    const std::string text = disk->parameters();
    for (size_t at = 0; at < text.size();) {
        const size_t end = std::min(text.find(' ', at), text.size());
        words.push_back(text.substr(at, end - at));
        at = end + 1;
    }
    auto again = make_source("disk", parse_source_parameters(words));
    EXPECT_EQ(again->total_flux(), disk->total_flux());
    EXPECT_EQ(again->parameters(), text);

    auto rect = make_source("rectangle",
                            parse_source_parameters({"size_x=2", "size_y=0.5", "radiance=0.1"}));
    EXPECT_DOUBLE_EQ(rect->total_flux(), kPi * 0.1 * 1.0);
    auto sphere = make_source("sphere", {});
    EXPECT_DOUBLE_EQ(sphere->total_flux(), 1.0);
    auto lobe = make_source("lobe", parse_source_parameters({"n=3", "intensity=2"}));
    EXPECT_DOUBLE_EQ(lobe->total_flux(), 2 * kPi * 2 / 4);

    auto cluster = make_source("cluster", {});
    const auto& chips = static_cast<const analytic::ChipCluster&>(*cluster).chips();
    ASSERT_EQ(chips.size(), 39u);  // 1 + 6 + 12 + 20
    EXPECT_DOUBLE_EQ(cluster->total_flux(), 1.0);
    EXPECT_EQ(chips[0].x, 0.0);
    EXPECT_NEAR(std::hypot(chips[1].x, chips[1].y), 2.0, 1e-12);    // ring 1 at the pitch
    EXPECT_NEAR(std::hypot(chips[38].x, chips[38].y), 6.0, 1e-12);  // ring 3 at 3 pitches
    EXPECT_EQ(chips[0].wavelength_nm, 630);
    EXPECT_EQ(chips[1].wavelength_nm, 530);
    EXPECT_EQ(chips[5].wavelength_nm, 460);
    // Luminous flux: 13 chips of each colour, each 1/39 W, weighted by 683.002 V(lambda).
    const double v = photopic_efficiency(630) + photopic_efficiency(530) + photopic_efficiency(460);
    EXPECT_NEAR(cluster->luminous_flux(), 13.0 / 39 * kMaxLuminousEfficacy * v, 1e-12);
}

TEST(SynthSources, BadNamesKeysAndValuesAreClearErrors) {
    EXPECT_EQ(error_of([] { make_source("cone", {}); }),
              "synth: unknown source 'cone' (known: disk, rectangle, sphere, lobe, cluster)");
    EXPECT_EQ(error_of([] {
                  make_source("disk", {{"radus", "1"}});
              }),
              "synth disk: unknown parameter 'radus' (known: radius, tilt, flux, radiance, "
              "wavelength, spectrum)");
    EXPECT_EQ(error_of([] {
                  make_source("disk", {{"tilt", "95"}});
              }),
              "disk: tilt must be a number of degrees from -90 to 90, not 95");
    EXPECT_EQ(error_of([] {
                  make_source("disk", {{"radius", "2mm"}});
              }),
              "synth disk: parameter 'radius' must be a finite number, not '2mm'");
    EXPECT_EQ(error_of([] {
                  make_source("disk", {{"radius", "nan"}});
              }),
              "synth disk: parameter 'radius' must be a finite number, not 'nan'");
    EXPECT_EQ(error_of([] {
                  make_source("disk", {{"radius", "-1"}});
              }),
              "disk: radius must be a positive number of mm, not -1");
    EXPECT_EQ(error_of([] {
                  make_source("sphere", {{"flux", "1"}, {"radiance", "2"}});
              }),
              "synth sphere: give either 'flux' or 'radiance', not both");
    EXPECT_EQ(error_of([] {
                  make_source("lobe", {{"n", "-0.5"}});
              }),
              "lobe: exponent n must be a number >= 0, not -0.5");
    EXPECT_EQ(error_of([] {
                  make_source("cluster", {{"rings", "1,6.5"}});
              }),
              "synth cluster: rings must be whole numbers of chips, not 6.5");
    EXPECT_EQ(error_of([] {
                  make_source("cluster", {{"rings", "3"}});
              }),
              "cluster: ring 1 has radius 0, so it holds one chip or none, not 3");
    EXPECT_EQ(error_of([] {
                  make_source("cluster", {{"pitch", "1.2"}});
              }),
              "cluster: chips 9 and 10 overlap; use a larger pitch or a smaller chip");
    EXPECT_EQ(error_of([] {
                  make_source("cluster", {{"wavelength", "530,,460"}});
              }),
              "synth cluster: parameter 'wavelength' must be a finite number, not ''");
    EXPECT_EQ(error_of([] { parse_source_parameters({"radius"}); }),
              "synth: expected key=value, not 'radius'");
    EXPECT_EQ(error_of([] { parse_source_parameters({"=1"}); }),
              "synth: expected key=value, not '=1'");
    EXPECT_EQ(error_of([] {
                  parse_source_parameters({"flux=1", "flux=2"});
              }),
              "synth: parameter 'flux' is given twice");
}

TEST(SynthSources, SpectrumFiles) {
    test::ScratchDir dir;
    const std::string good = dir.file("good.txt");
    test::write_file(good, "# nm  power\r\n450\t0.5\r\n500, 1\r\n550 0.25\r\n");
    auto disk = make_source("disk", {{"spectrum", good}});
    RayHeader h;
    disk->describe_spectrum(h);
    EXPECT_EQ(h.spectral, SpectralKind::shared_table);
    ASSERT_EQ(h.spectral_tables.size(), 1u);
    EXPECT_EQ(h.spectral_tables[0].wavelength, (std::vector<float>{450, 500, 550}));
    EXPECT_EQ(h.spectral_tables[0].weight, (std::vector<float>{0.5f, 1, 0.25f}));
    EXPECT_NEAR(disk->luminous_flux(), luminous_efficacy(h.spectral_tables[0]), 1e-12);
    EXPECT_EQ(disk->parameters(),
              "radius=1 radiance=" + format_double(1 / (kPi * kPi)) + " spectrum=" + good);

    auto bad = [&](const std::string& name, const std::string& content) {
        const std::string path = dir.file(name);
        test::write_file(path, content);
        return error_of([&] { read_spectrum_file(path); });
    };
    EXPECT_EQ(
        bad("a.txt", "450 1\n460 x\n"),
        dir.file("a.txt") +
            ": line 2: expected two numbers, wavelength (nm) and relative power, not '460 x'");
    EXPECT_EQ(bad("b.txt", "450 1\n440 1\n"),
              dir.file("b.txt") +
                  ": line 2: wavelength 440 nm does not ascend (the line before has 450 nm)");
    EXPECT_EQ(bad("c.txt", "450 1\n460 -1\n"),
              dir.file("c.txt") + ": line 2: relative power -1 is not a number >= 0");
    EXPECT_EQ(bad("d.txt", "450 1\n"),
              dir.file("d.txt") +
                  ": a spectrum needs at least two rows of wavelength (nm) and relative power");
    EXPECT_EQ(bad("e.txt", "450 0\n460 0\n"),
              dir.file("e.txt") + ": every relative power is zero: the spectrum carries no light");
    EXPECT_EQ(bad("f.txt", "inf 1\n460 1\n"),
              dir.file("f.txt") + ": line 1: wavelength inf nm is not a positive number");
}

// ---------------------------------------------------------------------------------------------

TEST(Synthesize, EqualFluxRaysDeterministicForASeed) {
    const auto disk = make_source("disk", {{"radius", "1.5"}, {"flux", "2"}});
    const uint64_t n = 100003;  // not a multiple of the chunk size
    SynthOptions options;
    options.chunk_size = 4096;
    MemoryEncoder a, b, c;
    synthesize(*disk, n, 11, a, options);
    synthesize(*disk, n, 11, b, options);
    synthesize(*disk, n, 12, c, options);
    ASSERT_TRUE(a.finished);
    ASSERT_EQ(a.rays.size(), n);
    ASSERT_EQ(b.rays.size(), n);
    EXPECT_EQ(std::memcmp(a.rays.data(), b.rays.data(), n * sizeof(Ray)), 0);
    EXPECT_NE(std::memcmp(a.rays.data(), c.rays.data(), n * sizeof(Ray)), 0);

    const float flux = float(2.0 / n);
    const float luminous = float(flux * kMaxLuminousEfficacy * photopic_efficiency(555));
    double sum = 0;
    for (const Ray& r : a.rays) {
        ASSERT_EQ(r.radiant, flux);
        ASSERT_EQ(r.luminous, luminous);
        sum += r.radiant;
    }
    EXPECT_NEAR(sum, 2.0, 2.0 * 6e-8);  // one float rounding of total / n

    // The chunking does not change the rays.
    MemoryEncoder d;
    synthesize(*disk, n, 11, d);
    EXPECT_EQ(std::memcmp(a.rays.data(), d.rays.data(), n * sizeof(Ray)), 0);
}

TEST(Synthesize, HeaderDescribesTheRays) {
    const auto disk =
        make_source("disk", {{"radius", "1.5"}, {"flux", "2"}, {"wavelength", "450"}});
    const RayHeader h = synth_header(*disk, 1000, 42);
    EXPECT_EQ(h.unit, LengthUnit::mm);
    EXPECT_EQ(h.ray_count, 1000u);
    EXPECT_TRUE(h.has_radiant);
    EXPECT_TRUE(h.has_luminous);
    EXPECT_EQ(h.stated_radiant, 2.0);
    EXPECT_NEAR(h.stated_luminous, 2.0 * kMaxLuminousEfficacy * photopic_efficiency(450), 1e-12);
    EXPECT_EQ(h.spectral, SpectralKind::single_wavelength);
    EXPECT_EQ(h.single_wavelength, 450.0f);
    EXPECT_EQ(h.creation_method, 0);
    EXPECT_EQ(h.text[0], "rayset synthetic disk");
    EXPECT_EQ(h.text[7], "disk " + disk->parameters() + " rays=1000 seed=42");

    const auto cluster = make_source("cluster", {});
    const RayHeader hc = synth_header(*cluster, 10, 1);
    EXPECT_EQ(hc.spectral, SpectralKind::per_ray_wavelength);
    EXPECT_EQ(hc.min_wavelength, 460.0f);
    EXPECT_EQ(hc.max_wavelength, 630.0f);
    EXPECT_TRUE(std::isnan(hc.stated_luminous));  // depends on which chips the rays drew
    EXPECT_DOUBLE_EQ(hc.stated_radiant, 1.0);     // 39 shares of 1/39 W
    const RayHeader plain = synth_header(*cluster, 10, 1, SynthOptions{false, 1, {}});
    EXPECT_FALSE(plain.has_luminous);
}

TEST(Synthesize, ClusterRaysCarryTheirChipsWavelengths) {
    // Equal chip fluxes: each of the three colours has 13 of 39 chips, so a third of the rays.
    // Bernstein bound at alpha = 1e-4 per colour.
    const auto cluster = make_source("cluster", {});
    MemoryEncoder out;
    const uint64_t n = 300000;
    synthesize(*cluster, n, 5, out);
    std::map<float, double> counts;
    double luminous = 0;
    for (const Ray& r : out.rays) {
        counts[r.wavelength] += 1;
        luminous += r.luminous;
        ASSERT_EQ(r.luminous,
                  float(r.radiant * kMaxLuminousEfficacy * photopic_efficiency(r.wavelength)));
    }
    ASSERT_EQ(counts.size(), 3u);
    for (const auto& [wavelength, count] : counts)
        EXPECT_NEAR(count, n / 3.0, test::bernstein_bound(double(n), 1.0 / 3, 1e-4))
            << wavelength << " nm";
    // The luminous total is a sum of per-colour shares, so within the colours' statistics.
    EXPECT_NEAR(luminous / cluster->luminous_flux(), 1.0, 0.02);
}

TEST(Synthesize, WritesAReadableTm25File) {
    test::ScratchDir dir;
    const std::string path = dir.file("disk.tm25ray");
    const auto disk = make_source("disk", {{"radius", "2"}, {"flux", "0.5"}});
    const uint64_t n = 20000;
    {
        auto out = create_rays(path, RayFormat::tm25, synth_header(*disk, n, 3));
        synthesize(*disk, n, 3, *out);
    }
    MemoryEncoder memory;
    synthesize(*disk, n, 3, memory);
    auto reader = open_rays(path);
    EXPECT_EQ(reader->header().ray_count, n);
    EXPECT_EQ(reader->header().text[0], "rayset synthetic disk");
    RayChunk chunk;
    size_t i = 0;
    while (reader->read(chunk))
        for (const Ray& r : chunk.rays) {
            const Ray& m = memory.rays[i++];
            ASSERT_TRUE(r.origin == m.origin && r.direction == m.direction &&
                        r.radiant == m.radiant)
                << "ray " << i;
        }
    EXPECT_EQ(i, n);
    EXPECT_NEAR(reader->totals().radiant, 0.5, 0.5 * 1e-7);
    EXPECT_TRUE(reader->warnings().empty());
}

TEST(Synthesize, RefusesZeroRays) {
    MemoryEncoder out;
    EXPECT_EQ(error_of([&] { synthesize(*make_source("disk", {}), 0, 1, out); }),
              "synth: the ray count must be at least 1");
}

}  // namespace
}  // namespace rayset
