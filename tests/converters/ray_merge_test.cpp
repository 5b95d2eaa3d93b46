#include "converters/colour/spectrum.h"
#include "converters/rays/ray_ops.h"

#include "ray_ops_test_support.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <cmath>

namespace rayset {
namespace {

using test::numbered_rays;
using test::read_rays;
using test::same_bits;
using test::ScratchDir;
using test::write_rays;

// A blue chip and a yellow phosphor, as OSRAM ships white LEDs: one table each.
const SpectralTable kBlue{{440, 450, 460}, {0.2f, 1, 0.3f}};
const SpectralTable kYellow{{520, 560, 600, 640}, {0.5f, 1, 0.8f, 0.2f}};

RayHeader table_header(const SpectralTable& table) {
    RayHeader h;
    h.has_radiant = true;
    h.spectral = SpectralKind::shared_table;
    h.spectral_tables = {table};
    return h;
}

double luminous_sum(const test::ReadBack& file) {
    PhotometricWeights w(file.header);
    double s = 0;
    for (const Ray& r : file.rays) s += w.luminous(r);
    return s;
}

bool contains(const std::vector<std::string>& lines, const std::string& part) {
    for (const std::string& l : lines)
        if (l.find(part) != std::string::npos) return true;
    return false;
}

TEST(Merge, BlueAndYellowBecomeOneFileWithATableIndexPerRay) {
    ScratchDir dir;
    const auto blue = numbered_rays(700, true, false, 1),
               yellow = numbered_rays(300, true, false, 2);
    write_rays(dir.file("blue.tm25ray"), RayFormat::tm25, table_header(kBlue), blue);
    write_rays(dir.file("yellow.tm25ray"), RayFormat::tm25, table_header(kYellow), yellow);
    RayOpReport report = merge_rays({dir.file("blue.tm25ray"), dir.file("yellow.tm25ray")},
                                    dir.file("white.tm25ray"), RayFormat::tm25);
    EXPECT_TRUE(report.warnings.empty()) << report.warnings[0];

    // Read back through TM-25: the merged file is a valid one.
    auto white = read_rays(dir.file("white.tm25ray"));
    auto b = read_rays(dir.file("blue.tm25ray")), y = read_rays(dir.file("yellow.tm25ray"));
    ASSERT_EQ(white.rays.size(), 1000u);
    EXPECT_EQ(white.header.spectral, SpectralKind::per_ray_table);
    ASSERT_EQ(white.header.spectral_tables.size(), 2u);
    EXPECT_EQ(white.header.spectral_tables[0].wavelength, kBlue.wavelength);
    EXPECT_EQ(white.header.spectral_tables[1].weight, kYellow.weight);
    for (size_t i = 0; i < 1000; ++i) {
        const Ray& in = i < 700 ? blue[i] : yellow[i - 700];
        EXPECT_EQ(white.rays[i].spectrum, i < 700 ? 0 : 1) << i;
        EXPECT_TRUE(same_bits(white.rays[i].origin, in.origin)) << i;
        EXPECT_EQ(white.rays[i].radiant, in.radiant) << i;
    }
    // Totals add: radiant exactly (the same f32 values summed), luminous through each table.
    EXPECT_NEAR(white.totals.radiant, b.totals.radiant + y.totals.radiant, 1e-12);
    EXPECT_NEAR(report.totals.radiant, white.totals.radiant, 1e-12);
    const double lb = luminous_sum(b), ly = luminous_sum(y);
    EXPECT_GT(ly, 3 * lb);  // the tables differ: a mix-up of indices would show
    EXPECT_NEAR(luminous_sum(white), lb + ly, 1e-9 * (lb + ly));
    EXPECT_NEAR(white.header.stated_radiant, b.totals.radiant + y.totals.radiant,
                1e-6);  // the header's f32
}

TEST(Merge, EqualTablesStayOneSharedTable) {
    ScratchDir dir;
    write_rays(dir.file("a.tm25ray"), RayFormat::tm25, table_header(kBlue),
               numbered_rays(10, true, false, 1));
    write_rays(dir.file("b.tm25ray"), RayFormat::tm25, table_header(kBlue),
               numbered_rays(20, true, false, 2));
    merge_rays({dir.file("a.tm25ray"), dir.file("b.tm25ray")}, dir.file("ab.tm25ray"),
               RayFormat::tm25);
    auto ab = read_rays(dir.file("ab.tm25ray"));
    EXPECT_EQ(ab.rays.size(), 30u);
    EXPECT_EQ(ab.header.spectral, SpectralKind::shared_table);
    EXPECT_EQ(ab.header.spectral_tables.size(), 1u);
}

TEST(Merge, SingleWavelengthsBecomePerRayWavelengthsUnlessEqual) {
    ScratchDir dir;
    RayHeader h;
    h.has_radiant = true;
    h.spectral = SpectralKind::single_wavelength;
    h.single_wavelength = 450;
    write_rays(dir.file("a.tm25ray"), RayFormat::tm25, h, numbered_rays(4, true, false, 1));
    write_rays(dir.file("a2.tm25ray"), RayFormat::tm25, h, numbered_rays(2, true, false, 3));
    h.single_wavelength = 600;
    write_rays(dir.file("b.tm25ray"), RayFormat::tm25, h, numbered_rays(3, true, false, 2));
    merge_rays({dir.file("a.tm25ray"), dir.file("b.tm25ray")}, dir.file("ab.tm25ray"),
               RayFormat::tm25);
    auto ab = read_rays(dir.file("ab.tm25ray"));
    EXPECT_EQ(ab.header.spectral, SpectralKind::per_ray_wavelength);
    ASSERT_EQ(ab.rays.size(), 7u);
    for (size_t i = 0; i < 7; ++i) EXPECT_EQ(ab.rays[i].wavelength, i < 4 ? 450.0f : 600.0f);
    EXPECT_EQ(ab.header.min_wavelength, 450.0f);
    EXPECT_EQ(ab.header.max_wavelength, 600.0f);

    merge_rays({dir.file("a.tm25ray"), dir.file("a2.tm25ray")}, dir.file("aa.tm25ray"),
               RayFormat::tm25);
    auto aa = read_rays(dir.file("aa.tm25ray"));
    EXPECT_EQ(aa.header.spectral, SpectralKind::single_wavelength);
    EXPECT_EQ(aa.header.single_wavelength, 450.0f);
}

TEST(Merge, LengthUnitsAreUnified) {
    ScratchDir dir;
    RayHeader h;
    h.has_radiant = true;
    const auto a = numbered_rays(5, true, false, 1), b = numbered_rays(5, true, false, 2);
    write_rays(dir.file("a.csv"), RayFormat::csv, h, a);
    h.unit = LengthUnit::cm;
    write_rays(dir.file("b.csv"), RayFormat::csv, h, b);
    merge_rays({dir.file("a.csv"), dir.file("b.csv")}, dir.file("ab.csv"), RayFormat::csv);
    auto ab = read_rays(dir.file("ab.csv"));
    EXPECT_EQ(ab.header.unit, LengthUnit::mm);
    EXPECT_TRUE(same_bits(ab.rays[2].origin, a[2].origin));
    EXPECT_EQ(ab.rays[7].origin.x, float(double(b[2].origin.x) * 10));
    EXPECT_EQ(ab.rays[7].origin.y, float(double(b[2].origin.y) * 10));

    MergeOptions in_metres;
    in_metres.unit = LengthUnit::m;
    merge_rays({dir.file("a.csv"), dir.file("b.csv")}, dir.file("m.csv"), RayFormat::csv,
               in_metres);
    auto m = read_rays(dir.file("m.csv"));
    EXPECT_EQ(m.header.unit, LengthUnit::m);
    EXPECT_EQ(m.rays[3].origin.y, float(double(a[3].origin.y) / 1000));
    EXPECT_EQ(m.rays[8].origin.y, float(double(b[3].origin.y) / 100));
}

// A luminous-only file (no spectrum) with a radiant file with a table: luminous flux can be
// known for both (the second through its table), radiant flux not for the first.
TEST(Merge, MissingColumnsAreDerivedWhereTheSpectrumAllowsElseDropped) {
    ScratchDir dir;
    RayHeader lum;
    lum.has_luminous = true;
    const auto a = numbered_rays(6, false, true, 1), b = numbered_rays(4, true, false, 2);
    write_rays(dir.file("a.tm25ray"), RayFormat::tm25, lum, a);
    write_rays(dir.file("b.tm25ray"), RayFormat::tm25, table_header(kYellow), b);
    RayOpReport report = merge_rays({dir.file("a.tm25ray"), dir.file("b.tm25ray")},
                                    dir.file("ab.tm25ray"), RayFormat::tm25);
    EXPECT_TRUE(contains(report.warnings, "spectral data dropped"))
        << ::testing::PrintToString(report.warnings);
    EXPECT_TRUE(contains(report.warnings, "radiant flux of " + dir.file("b.tm25ray") + " dropped"));
    auto ab = read_rays(dir.file("ab.tm25ray"));
    EXPECT_FALSE(ab.header.has_radiant);
    EXPECT_TRUE(ab.header.has_luminous);
    EXPECT_EQ(ab.header.spectral, SpectralKind::none);
    const double efficacy = luminous_efficacy(kYellow);
    for (size_t i = 0; i < 6; ++i) EXPECT_EQ(ab.rays[i].luminous, a[i].luminous);
    for (size_t i = 0; i < 4; ++i)
        EXPECT_FLOAT_EQ(ab.rays[6 + i].luminous, float(b[i].radiant * efficacy));
}

TEST(Merge, NoCommonFluxIsAnError) {
    ScratchDir dir;
    RayHeader rad, lum;
    rad.has_radiant = true;
    lum.has_luminous = true;
    write_rays(dir.file("w.tm25ray"), RayFormat::tm25, rad, numbered_rays(3, true, false));
    write_rays(dir.file("lm.tm25ray"), RayFormat::tm25, lum, numbered_rays(3, false, true));
    try {
        merge_rays({dir.file("w.tm25ray"), dir.file("lm.tm25ray")}, dir.file("o.tm25ray"),
                   RayFormat::tm25);
        ADD_FAILURE() << "merged";
    } catch (const Error& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("no flux column (radiant or luminous) is known for every input"),
                  std::string::npos)
            << m;
        EXPECT_NE(m.find(dir.file("lm.tm25ray") + " carries luminous flux without spectral data"),
                  std::string::npos)
            << m;
    }
    EXPECT_FALSE(std::filesystem::exists(dir.file("o.tm25ray")));
}

TEST(Merge, FarFieldWithNearFieldIsAnError) {
    ScratchDir dir;
    RayHeader h;
    h.has_radiant = true;
    write_rays(dir.file("near.csv"), RayFormat::csv, h, numbered_rays(3, true, false));
    h.far_field = true;
    write_rays(dir.file("far.csv"), RayFormat::csv, h, numbered_rays(3, true, false));
    try {
        merge_rays({dir.file("near.csv"), dir.file("far.csv")}, dir.file("o.csv"), RayFormat::csv);
        ADD_FAILURE() << "merged";
    } catch (const Error& e) {
        const std::string m = e.what();
        EXPECT_EQ(m.rfind(dir.file("far.csv"), 0), 0u) << m;
        EXPECT_NE(m.find("cannot merge far-field rays"), std::string::npos) << m;
    }
}

TEST(Merge, ExtraColumnsAreUnitedWithNaNWhereMissing) {
    ScratchDir dir;
    RayHeader h;
    h.has_radiant = true;
    write_rays(dir.file("plain.csv"), RayFormat::csv, h, numbered_rays(2, true, false));
    h.extras = {{ExtraKind::additional, "temperature"}};
    write_rays(dir.file("warm.csv"), RayFormat::csv, h, numbered_rays(2, true, false), {25, 26});
    RayOpReport report = merge_rays({dir.file("plain.csv"), dir.file("warm.csv")},
                                    dir.file("o.csv"), RayFormat::csv);
    EXPECT_TRUE(
        contains(report.warnings, dir.file("plain.csv") + " has no extra column 'temperature'"));
    auto o = read_rays(dir.file("o.csv"));
    ASSERT_EQ(o.header.extras.size(), 1u);
    ASSERT_EQ(o.extra.size(), 4u);
    EXPECT_TRUE(std::isnan(o.extra[0]) && std::isnan(o.extra[1]));
    EXPECT_EQ(o.extra[2], 25);
    EXPECT_EQ(o.extra[3], 26);
}

}  // namespace
}  // namespace rayset
