// The 14 real IES and EULUMDAT files: figures read off the files by hand, total flux against the
// lumens the files state, and round trips IES -> IES, LDT -> LDT, IES -> LDT -> IES, LDT -> IES ->
// LDT.
#include "converters/photometry/eulumdat.h"
#include "converters/photometry/ies.h"
#include "converters/photometry/photometry.h"
#include "core/error.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace rayset {
namespace {

using test::shared_data;

constexpr double pi = 3.14159265358979323846;
const std::string luxeon =
    "S01.01.02.354_MAXWELL-8-T4_LUXEON_5050_Square_with_glass-MEASURED_IESNA.ies";
const std::string ledvance = "4058075580602_FL_MAX_LUM_600W_757_SYM_60_WAL.ldt";
const std::vector<std::string> ies_files = {"1.IES",         "2.IES",
                                            "3.IES",         "7.IES",
                                            "flood_2.1.IES", "ABSOLUTE_LED.ies",
                                            luxeon,          "TILT_TEST_SYNTHETIC.ies"};
const std::vector<std::string> ldt_files = {"0-0-0.ldt", "0-2-0.ldt", "0-3-0.ldt",
                                            "0-4-0.ldt", "1-1-0.ldt", ledvance};

std::string path_of(const std::string& name) { return shared_data("photometry/" + name); }

// The labs' lumens come from their own quadrature of the same grid. Both rules are exact for
// constants and differ by O(d^2) for a curved distribution: for a 5 degree step d, d^2/8 is
// 0.1 % per rule, so two rules agree within 0.2 %.
constexpr double stated_lumens_tolerance = 0.002;

TEST(PhotometryRealData, AllFourteenFilesRead) {
    RAYSET_REQUIRE_SHARED_DATA();
    for (const auto& name : ies_files) {
        EXPECT_EQ(detect_photometry_format(path_of(name)), PhotometryFormat::ies) << name;
        EXPECT_NO_THROW(read_photometry(path_of(name))) << name;
    }
    for (const auto& name : ldt_files) {
        EXPECT_EQ(detect_photometry_format(path_of(name)), PhotometryFormat::eulumdat) << name;
        EXPECT_NO_THROW(read_photometry(path_of(name))) << name;
    }
}

TEST(PhotometryRealData, QuadrantFeetAbsolute_1) {
    RAYSET_REQUIRE_SHARED_DATA();
    IesFile f = read_ies(path_of("1.IES"));
    EXPECT_EQ(f.version, IesVersion::lm63_2002);
    EXPECT_EQ(f.keywords.front().key, "TEST");
    EXPECT_EQ(
        f.keywords[5].value,
        "FROSTED TRANSLUCENT PLASTIC DIFFUSER, SANDWICHED BETWEEN CAST\nMETAL HOUSING AND CAST "
        "METAL "
        "HEAT SINK, DIFFUSER FROSTED SIDE\nIN, 4 WHITE CIRCUIT BOARD EACH WITH 48 LEDS, MOLDED "
        "PLASTIC\nREFLECTOR WITH SPECULAR FINISH.");
    EXPECT_EQ(f.multiplier, 1.032007);
    Photometry p = ies_to_photometry(f);
    EXPECT_EQ(p.vertical_deg.size(), 74u);
    EXPECT_EQ(p.vertical_deg[27], 66);  // the extra angle between 65 and 67.5
    EXPECT_EQ(p.horizontal_deg,
              (std::vector<double>{0, 5, 15, 25, 35, 45, 46, 55, 65, 75, 85, 90}));
    EXPECT_EQ(p.lamp_count, 192);
    EXPECT_TRUE(std::isnan(p.rated_lumens));
    EXPECT_EQ(p.candela.front(), 389.0 * 1.032007);  // multiplier applied once
    EXPECT_EQ(p.candela.back(), 15.0 * 1.032007);
    EXPECT_EQ(p.width_m, 1.47 * 0.3048);
    EXPECT_EQ(p.height_m, 0.2375 * 0.3048);
    EXPECT_FALSE(p.round);
    EXPECT_EQ(p.input_watts, 69.6);
    EXPECT_EQ(p.keywords.at("_ABSOLUTELUMENS"), "9217");
    // Measured 9218.80 lm: 0.02 % from the file's 9217 lm.
    EXPECT_NEAR(p.total_flux(), 9217, stated_lumens_tolerance * 9217);
}

TEST(PhotometryRealData, BilateralRoundOpening_2) {
    RAYSET_REQUIRE_SHARED_DATA();
    Photometry p = read_photometry(path_of("2.IES"));
    EXPECT_EQ(p.vertical_deg.size(), 73u);
    EXPECT_EQ(p.horizontal_deg.size(), 22u);
    EXPECT_EQ(p.horizontal_deg[5], 41);
    EXPECT_EQ(p.horizontal_deg.back(), 180);
    EXPECT_EQ(p.lamp_count, 4);
    EXPECT_EQ(p.candela.front(), 1732.0 * 1.045644);
    EXPECT_EQ(p.candela.back(), 1.0 * 1.045644);
    EXPECT_TRUE(p.round);
    EXPECT_EQ(p.width_m, 0.69 * 0.3048);
    EXPECT_EQ(p.length_m, 0.69 * 0.3048);
    EXPECT_EQ(p.input_watts, 55.1);
    // Measured 5832.88 lm: 0.02 % from the stated 5834.
    EXPECT_NEAR(p.total_flux(), 5834, stated_lumens_tolerance * 5834);
}

TEST(PhotometryRealData, FullCircleMetres_3) {
    RAYSET_REQUIRE_SHARED_DATA();
    Photometry p = read_photometry(path_of("3.IES"));
    EXPECT_EQ(p.vertical_deg.size(), 37u);
    EXPECT_EQ(p.horizontal_deg.size(), 25u);
    EXPECT_EQ(p.horizontal_deg.back(), 360);
    EXPECT_EQ(p.width_m, 0.21);
    EXPECT_EQ(p.length_m, 0.16);
    EXPECT_EQ(p.candela.front(), 4895.584 * 1.0043784);
    // The C360 plane repeats C0, as LM-63 asks.
    EXPECT_TRUE(std::equal(p.candela.begin(), p.candela.begin() + 37, p.candela.end() - 37));
    // The file states no lumens; Photometric Toolbox gives 13359.57 lm (listed in the origin
    // repository's ies/ies_summary.md). Measured 13342.87 lm: 0.13 %.
    EXPECT_NEAR(p.total_flux(), 13359.57, stated_lumens_tolerance * 13359.57);
}

TEST(PhotometryRealData, AxialRoundOpening_7) {
    RAYSET_REQUIRE_SHARED_DATA();
    Photometry p = read_photometry(path_of("7.IES"));
    EXPECT_EQ(p.vertical_deg.size(), 37u);
    EXPECT_EQ(p.vertical_deg.back(), 90);
    EXPECT_EQ(p.horizontal_deg, std::vector<double>{0});
    EXPECT_EQ(p.lamp_count, 24);
    EXPECT_EQ(p.candela.front(), 269);
    EXPECT_EQ(p.candela.back(), 0);
    EXPECT_EQ(p.intensity(123, 0), 269);  // the same in every plane
    EXPECT_EQ(p.intensity(0, 120), 0);    // nothing measured above the horizon
    EXPECT_TRUE(p.round);
    EXPECT_EQ(p.width_m, 0.453125 * 0.3048);
    // Measured 531.71 lm: 0.05 % from the stated 532.
    EXPECT_NEAR(p.total_flux(), 532, stated_lumens_tolerance * 532);
}

TEST(PhotometryRealData, TypeBFloodlight) {
    RAYSET_REQUIRE_SHARED_DATA();
    Photometry p = read_photometry(path_of("flood_2.1.IES"));
    EXPECT_EQ(p.type, PhotometricType::B);
    EXPECT_EQ(p.vertical_deg.size(), 45u);
    EXPECT_EQ(p.vertical_deg.front(), -90);
    EXPECT_EQ(p.vertical_deg.back(), 90);
    EXPECT_EQ(p.horizontal_deg.size(), 23u);
    EXPECT_EQ(p.horizontal_deg[10], 19.5);
    EXPECT_EQ(p.lamp_count, 144);
    EXPECT_EQ(p.input_watts, 74.1);
    EXPECT_EQ(p.candela[2], 98);
    EXPECT_EQ(p.max_candela(), 5287);
    // Type B frame: the horizontal angle is the latitude toward the lateral polar axis (weight
    // cos H), the vertical angle the rotation about that axis. This gives 10707 lm, 1.0 % above
    // the stated 10601 lm; weighting cos V instead (the axes swapped) would give 11331 lm, 6.9 %
    // off. Other quadratures of this grid (exact bilinear, point trapezoid, cell mean) agree with
    // ours within 0.3 %, so the 1 % is the lab's own rule; 2 % accepts it and still rejects the
    // swapped frame.
    EXPECT_NEAR(p.total_flux(), 10601, 0.02 * 10601);
    EXPECT_THROW(write_photometry(testing::TempDir() + "/flood.ldt", p, PhotometryFormat::eulumdat),
                 Error);
}

TEST(PhotometryRealData, RelativePhotometryLm63_1995) {
    RAYSET_REQUIRE_SHARED_DATA();
    IesFile f = read_ies(path_of(luxeon));
    EXPECT_EQ(f.version, IesVersion::lm63_1995);
    Photometry p = ies_to_photometry(f);
    EXPECT_EQ(p.rated_lumens, 1000);
    EXPECT_EQ(p.vertical_deg.size(), 91u);
    EXPECT_EQ(p.horizontal_deg.size(), 73u);
    EXPECT_EQ(p.horizontal_deg[1], 5);
    EXPECT_EQ(p.candela.front(), 179.714);
    EXPECT_EQ(p.candela.back(), 0.623);
    EXPECT_EQ(p.input_watts, 29.343);
    // Relative photometry: luminaire flux over rated lamp flux is the efficiency (0.99993 here).
    double efficiency = p.total_flux() / p.rated_lumens;
    EXPECT_GT(efficiency, 0);
    EXPECT_LE(efficiency, 1.05);
}

TEST(PhotometryRealData, SyntheticAbsoluteAndTilt) {
    RAYSET_REQUIRE_SHARED_DATA();
    Photometry a = read_photometry(path_of("ABSOLUTE_LED.ies"));
    EXPECT_TRUE(std::isnan(a.rated_lumens));
    EXPECT_EQ(a.vertical_deg.size(), 19u);
    EXPECT_EQ(a.horizontal_deg.size(), 37u);
    EXPECT_EQ(a.candela.front(), 3500);
    EXPECT_EQ(a.height_m, 0.1);
    EXPECT_EQ(a.intensity(0, 15), a.intensity(215, 15));  // every plane the same

    IesFile t = read_ies(path_of("TILT_TEST_SYNTHETIC.ies"));
    EXPECT_EQ(t.keywords[3].value, "TILT=INCLUDE Test Fixture");  // a keyword, not the TILT line
    EXPECT_EQ(t.tilt.kind, IesTilt::Kind::include);
    EXPECT_EQ(t.tilt.lamp_to_luminaire_geometry, 1);
    EXPECT_EQ(t.tilt.angles_deg, (std::vector<double>{0, 45, 90, 180}));
    EXPECT_EQ(t.tilt.multipliers, (std::vector<double>{1, 0.9, 0.8, 1}));
    Photometry p = ies_to_photometry(t);
    EXPECT_EQ(p.candela, (std::vector<double>{1000, 900, 700, 400, 100}));
    EXPECT_EQ(p.rated_lumens, 1000);
    EXPECT_EQ(p.input_watts, 10);
}

TEST(PhotometryRealData, EulumdatTemplatesEveryIsym) {
    RAYSET_REQUIRE_SHARED_DATA();
    struct Case {
        std::string name;
        int isym;
        size_t planes;
        double first, last;
    } cases[] = {{"0-0-0.ldt", 0, 24, 0, 345},
                 {"0-2-0.ldt", 2, 13, 0, 180},
                 {"0-3-0.ldt", 3, 13, 90, 270},
                 {"0-4-0.ldt", 4, 7, 0, 90},
                 {"1-1-0.ldt", 1, 1, 0, 0}};
    for (const auto& c : cases) {
        SCOPED_TRACE(c.name);
        EulumdatFile f = read_eulumdat(path_of(c.name));
        EXPECT_EQ(f.isym, c.isym);
        EXPECT_EQ(f.ng, 19);
        EXPECT_EQ(f.intensities.size(), c.planes * 19);
        Photometry p = eulumdat_to_photometry(f);
        EXPECT_EQ(p.horizontal_deg.size(), c.planes);
        EXPECT_EQ(p.horizontal_deg.front(), c.first);
        EXPECT_EQ(p.horizontal_deg.back(), c.last);
        // 1 cd/klm of a 1 lm lamp is 0.001 cd, on 0..90: flux 2 pi x 0.001 lm exactly.
        EXPECT_EQ(p.candela.front(), 0.001);
        EXPECT_NEAR(p.total_flux(), 2 * pi * 0.001, 1e-15);
        EXPECT_EQ(p.input_watts, 0.1);
    }
    EulumdatFile f = read_eulumdat(path_of("1-1-0.ldt"));
    EXPECT_EQ(f.ityp, 2);
    EXPECT_EQ(f.company, "Test Laboratory");
    EXPECT_EQ(f.luminaire_name, "Downlight");
    EXPECT_EQ(f.lamp_sets[0].color, "4000K");
    EXPECT_EQ(f.lamp_sets[0].rendering, "1B/80");
}

TEST(PhotometryRealData, LedvanceFloodlightLorlTimesLampLumens) {
    RAYSET_REQUIRE_SHARED_DATA();
    EulumdatFile f = read_eulumdat(path_of(ledvance));
    EXPECT_EQ(f.isym, 0);
    EXPECT_EQ(f.mc, 16);
    EXPECT_EQ(f.dc, 22.5);
    EXPECT_EQ(f.ng, 37);
    EXPECT_EQ(f.dg, 2.5);
    EXPECT_EQ(f.luminaire_length_mm, 500);
    EXPECT_EQ(f.luminous_width_mm, 300);
    EXPECT_EQ(f.lamp_sets.size(), 1u);
    EXPECT_EQ(f.lamp_sets[0].lumens, 80500);
    EXPECT_EQ(f.lamp_sets[0].color, "5700");
    EXPECT_EQ(f.intensities.front(), 948.12);
    EXPECT_EQ(f.intensities.back(), 0.02);
    Photometry p = eulumdat_to_photometry(f);
    EXPECT_EQ(p.candela.front(), 948.12 * 80.5);
    EXPECT_EQ(p.input_watts, 600);
    EXPECT_EQ(p.keywords.at("MANUFAC"), "LEDVANCE GmbH");
    // LORL 99.9 % of 80500 lm = 80419.5 lm; measured 80379.55 lm, 0.05 % below.
    EXPECT_NEAR(p.total_flux(), 0.999 * 80500, stated_lumens_tolerance * 0.999 * 80500);
}

// ---- round trips -----------------------------------------------------------------------------

void expect_same_values(const Photometry& a, const Photometry& b, double rel) {
    ASSERT_EQ(a.type, b.type);
    ASSERT_EQ(a.vertical_deg, b.vertical_deg);
    for (double h : a.horizontal_deg)
        for (double v : a.vertical_deg) {
            double x = a.intensity(h, v), y = b.intensity(h, v);
            ASSERT_NEAR(y, x, rel * std::max(1.0, x)) << "at " << h << ", " << v;
        }
    EXPECT_NEAR(b.total_flux(), a.total_flux(), rel * a.total_flux());
    EXPECT_EQ(a.lamp_count, b.lamp_count);
    EXPECT_EQ(std::isnan(a.rated_lumens), std::isnan(b.rated_lumens));
    if (!std::isnan(a.rated_lumens)) {
        EXPECT_NEAR(b.rated_lumens, a.rated_lumens, rel * a.rated_lumens);
    }
    EXPECT_EQ(a.input_watts, b.input_watts);
    EXPECT_NEAR(b.width_m, a.width_m, 1e-15);
    EXPECT_NEAR(b.length_m, a.length_m, 1e-15);
    EXPECT_NEAR(b.height_m, a.height_m, 1e-15);
    EXPECT_EQ(a.round, b.round);
}

TEST(PhotometryRealData, IesToIesIsExact) {
    RAYSET_REQUIRE_SHARED_DATA();
    test::ScratchDir dir;
    for (const auto& name : ies_files) {
        SCOPED_TRACE(name);
        // File level: every field, keyword order and TILT data.
        IesFile f = read_ies(path_of(name));
        write_ies(dir.file("f.ies"), f);
        IesFile g = read_ies(dir.file("f.ies"));
        ASSERT_EQ(g.keywords.size(), f.keywords.size());
        for (size_t i = 0; i < f.keywords.size(); ++i)
            EXPECT_EQ(g.keywords[i].value, f.keywords[i].value);
        EXPECT_EQ(g.version, f.version);
        EXPECT_EQ(g.tilt.multipliers, f.tilt.multipliers);
        EXPECT_EQ(g.candela, f.candela);
        EXPECT_EQ(g.multiplier, f.multiplier);
        EXPECT_EQ(g.width, f.width);
        // Photometry level: the same values, bit for bit.
        Photometry p = read_photometry(path_of(name));
        write_photometry(dir.file("p.ies"), p, PhotometryFormat::ies);
        Photometry q = read_photometry(dir.file("p.ies"));
        EXPECT_EQ(q.candela, p.candela);
        EXPECT_EQ(q.horizontal_deg, p.horizontal_deg);
        EXPECT_EQ(q.vertical_deg, p.vertical_deg);
        EXPECT_EQ(q.width_m, p.width_m);
        EXPECT_EQ(q.keywords, p.keywords);
        expect_same_values(p, q, 0);
    }
}

TEST(PhotometryRealData, IesToLdtToIesKeepsWhatBothHold) {
    RAYSET_REQUIRE_SHARED_DATA();
    test::ScratchDir dir;
    for (const auto& name : ies_files) {
        Photometry p = read_photometry(path_of(name));
        if (p.type != PhotometricType::C) continue;  // EULUMDAT has no type B (checked above)
        SCOPED_TRACE(name);
        write_photometry(dir.file("x.ldt"), p, PhotometryFormat::eulumdat);
        write_photometry(dir.file("x.ies"), read_photometry(dir.file("x.ldt")),
                         PhotometryFormat::ies);
        Photometry q = read_photometry(dir.file("x.ies"));
        // cd -> cd/klm -> cd, m -> mm -> m: equal to rounding.
        expect_same_values(p, q, 1e-13);
        for (const char* key : {"TEST", "MANUFAC", "LUMINAIRE", "LUMCAT", "ISSUEDATE", "LAMP"}) {
            auto it = p.keywords.find(key);
            if (it == p.keywords.end()) continue;
            std::string expected = it->second;
            std::replace(expected.begin(), expected.end(), '\n', ' ');  // EULUMDAT text is one line
            auto back = q.keywords.find(key);  // an empty line maps to no keyword
            EXPECT_EQ(back == q.keywords.end() ? "" : back->second, expected) << key;
        }
    }
}

TEST(PhotometryRealData, LdtToLdtAndThroughIes) {
    RAYSET_REQUIRE_SHARED_DATA();
    test::ScratchDir dir;
    for (const auto& name : ldt_files) {
        SCOPED_TRACE(name);
        EulumdatFile a = read_eulumdat(path_of(name));
        write_eulumdat(dir.file("f.ldt"), a);
        EulumdatFile b = read_eulumdat(dir.file("f.ldt"));
        EXPECT_EQ(b.intensities, a.intensities);
        EXPECT_EQ(b.c_angles_deg, a.c_angles_deg);
        EXPECT_EQ(b.light_output_ratio_percent, a.light_output_ratio_percent);

        Photometry p = read_photometry(path_of(name));
        write_photometry(dir.file("p.ldt"), p, PhotometryFormat::eulumdat);
        expect_same_values(p, read_photometry(dir.file("p.ldt")), 1e-13);
        write_photometry(dir.file("p.ies"), p, PhotometryFormat::ies);
        write_photometry(dir.file("q.ldt"), read_photometry(dir.file("p.ies")),
                         PhotometryFormat::eulumdat);
        EulumdatFile c = read_eulumdat(dir.file("q.ldt"));
        EXPECT_EQ(c.company, a.company);
        EXPECT_EQ(c.luminaire_name, a.luminaire_name);
        EXPECT_EQ(c.ityp, a.ityp);
        EXPECT_EQ(c.downward_flux_percent, a.downward_flux_percent);
        EXPECT_EQ(c.light_output_ratio_percent, a.light_output_ratio_percent);
        EXPECT_EQ(c.lamp_sets[0].lumens, a.lamp_sets[0].lumens);
        EXPECT_EQ(c.lamp_sets[0].rendering, a.lamp_sets[0].rendering);
        EXPECT_EQ(c.gamma_angles_deg, a.gamma_angles_deg);
        EXPECT_EQ(c.luminaire_height_mm, a.luminaire_height_mm);
        // The templates hold 1 cd/klm everywhere: every plane equal, so the writer picks Isym 1.
        bool uniform = std::all_of(a.intensities.begin(), a.intensities.end(),
                                   [&](double x) { return x == a.intensities[0]; });
        EXPECT_EQ(c.isym, uniform ? 1 : a.isym);
        if (!uniform) {
            ASSERT_EQ(c.intensities.size(), a.intensities.size());
            for (size_t i = 0; i < a.intensities.size(); ++i)
                EXPECT_NEAR(c.intensities[i], a.intensities[i], 1e-13 * a.intensities[i]);
        }
    }
}

}  // namespace
}  // namespace rayset
