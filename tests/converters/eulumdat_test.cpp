// EULUMDAT: every Isym with its stored planes, cd/klm -> cd, lamp sets, round trips through
// files and through Photometry and IES, and bad input with the message it must give.
#include "converters/photometry/eulumdat.h"
#include "converters/photometry/ies.h"
#include "converters/photometry/photometry.h"
#include "core/error.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

namespace rayset {
namespace {

using test::ScratchDir;
using test::write_file;

std::string read_error(const std::string& path) {
    try {
        read_eulumdat(path);
    } catch (const Error& e) {
        return e.what();
    }
    ADD_FAILURE() << "no error reading " << path;
    return {};
}

// An LDT text: header fields fixed, C planes every 360/mc degrees, gamma 0..180 every 180/(ng-1);
// stored plane k, gamma j has the value 100 k + j + 0.5 (cd/klm). Line numbers: C angles start
// at line 43 + 6 (extra lamp sets), intensities after the ng gamma lines.
std::string ldt_text(int isym, int mc, int ng, const std::string& lamp_count = "2",
                     const std::string& extra_sets = "") {
    std::ostringstream s;
    int sets = 1 + int(std::count(extra_sets.begin(), extra_sets.end(), '\n')) / 6;
    s << "ACME Lights\n3\n"
      << isym << "\n"
      << mc << "\n"
      << 360.0 / mc << "\n"
      << ng << "\n"
      << 180.0 / (ng - 1) << "\n";
    s << "RPT-7\nSpot 1\nSP-1\nspot.ldt\n2024-01-15 / lab\n";
    s << "120\n80\n40\n100\n60\n10\n11\n12\n13\n";  // luminaire and luminous area (mm)
    s << "95,5\n80\n1\n0\n" << sets << "\n";        // DFF with a decimal comma, LORL, CF, tilt
    s << lamp_count << "\nLED module\n1500\n3000 K\n1B\n22.5\n" << extra_sets;
    for (int i = 0; i < 10; ++i) s << 0.5 + i * 0.05 << "\n";
    for (int i = 0; i < mc; ++i) s << i * 360.0 / mc << "\n";
    for (int j = 0; j < ng; ++j) s << j * 180.0 / (ng - 1) << "\n";
    size_t planes = eulumdat_stored_planes(isym, mc);
    for (size_t k = 0; k < planes; ++k)
        for (int j = 0; j < ng; ++j) s << 100 * k + j + 0.5 << "\n";
    return s.str();
}

double stored(size_t k, size_t j) { return 100.0 * k + j + 0.5; }

TEST(EulumdatRead, FieldsLampSetsAndCdPerKlm) {
    ScratchDir dir;
    write_file(dir.file("a.ldt"), ldt_text(0, 4, 3, "2", "1\nspare lamp\n900\n4000 K\n1A\n10\n"));
    EulumdatFile f = read_eulumdat(dir.file("a.ldt"));
    EXPECT_EQ(f.company, "ACME Lights");
    EXPECT_EQ(f.ityp, 3);
    EXPECT_EQ(f.mc, 4);
    EXPECT_EQ(f.dc, 90);
    EXPECT_EQ(f.downward_flux_percent, 95.5);  // "95,5"
    ASSERT_EQ(f.lamp_sets.size(), 2u);
    EXPECT_EQ(f.lamp_sets[1].type, "spare lamp");
    EXPECT_EQ(f.lamp_sets[1].lumens, 900);
    EXPECT_EQ(f.direct_ratios[9], 0.5 + 9 * 0.05);

    Photometry p = eulumdat_to_photometry(f);
    EXPECT_EQ(p.horizontal_deg, (std::vector<double>{0, 90, 180, 270}));
    EXPECT_EQ(p.vertical_deg, (std::vector<double>{0, 90, 180}));
    // cd = cd/klm x 1500 lm / 1000 (lamp set 1; set 2 is alternative equipment)
    EXPECT_EQ(p.candela[p.index(3, 1)], stored(3, 1) * 1.5);
    EXPECT_EQ(p.rated_lumens, 1500);
    EXPECT_EQ(p.lamp_count, 2);
    EXPECT_EQ(p.input_watts, 22.5);
    EXPECT_EQ(p.length_m, 0.1);
    EXPECT_EQ(p.width_m, 0.06);
    EXPECT_EQ(p.height_m, 0.013);  // the largest of the four luminous heights
    EXPECT_EQ(p.keywords.at("MANUFAC"), "ACME Lights");
    EXPECT_EQ(p.keywords.at("TEST"), "RPT-7");
    EXPECT_EQ(p.keywords.at("LUMINAIRE"), "Spot 1");
    EXPECT_EQ(p.keywords.at("LUMCAT"), "SP-1");
    EXPECT_EQ(p.keywords.at("LAMP"), "LED module");
    EXPECT_EQ(p.keywords.at("_LDT_MORE_LAMP_SETS"), "1|spare lamp|900|4000 K|1A|10");
}

TEST(EulumdatRead, EverySymmetryUnfoldsToTheStoredPlanes) {
    ScratchDir dir;
    for (int isym = 0; isym <= 4; ++isym) {
        write_file(dir.file("s.ldt"), ldt_text(isym, 8, 5));
        Photometry p = read_photometry(dir.file("s.ldt"));
        SCOPED_TRACE("Isym " + std::to_string(isym));
        const double k = 1.5;  // 1500 lm / 1000
        switch (isym) {
            case 0:
                EXPECT_EQ(p.horizontal_deg.size(), 8u);
                EXPECT_EQ(p.intensity(315, 45), stored(7, 1) * k);
                break;
            case 1:
                EXPECT_EQ(p.horizontal_deg, std::vector<double>{0});
                EXPECT_EQ(p.intensity(123, 45), stored(0, 1) * k);
                break;
            case 2:  // C0 .. C180 stored, C225 is the mirror of C135
                EXPECT_EQ(p.horizontal_deg, (std::vector<double>{0, 45, 90, 135, 180}));
                EXPECT_EQ(p.intensity(225, 90), stored(3, 2) * k);
                break;
            case 3:  // stored from C270 (index 3 mc/4) through C0 to C90; C135 mirrors C45, C180 is
                     // C0
                EXPECT_EQ(p.horizontal_deg, (std::vector<double>{90, 135, 180, 225, 270}));
                EXPECT_EQ(p.intensity(270, 0), stored(0, 0) * k);
                EXPECT_EQ(p.intensity(315, 0), stored(1, 0) * k);
                EXPECT_EQ(p.intensity(0, 0), stored(2, 0) * k);
                EXPECT_EQ(p.intensity(45, 180), stored(3, 4) * k);
                EXPECT_EQ(p.intensity(135, 180), stored(3, 4) * k);
                EXPECT_EQ(p.intensity(90, 90), stored(4, 2) * k);
                break;
            case 4:  // C0 .. C90 stored
                EXPECT_EQ(p.horizontal_deg, (std::vector<double>{0, 45, 90}));
                EXPECT_EQ(p.intensity(135, 90), stored(1, 2) * k);
                EXPECT_EQ(p.intensity(270, 90), stored(2, 2) * k);
                break;
        }
    }
}

TEST(EulumdatRead, ByteOrderMarkAndDosEndOfFileMark) {
    ScratchDir dir;
    write_file(dir.file("b.ldt"), "\xEF\xBB\xBF" + ldt_text(1, 1, 3) + "\x1a\n");
    EXPECT_EQ(detect_photometry_format(dir.file("b.ldt")), PhotometryFormat::eulumdat);
    EXPECT_EQ(read_eulumdat(dir.file("b.ldt")).company, "ACME Lights");
}

TEST(EulumdatRead, AbsolutePhotometryFromANegativeLampCount) {
    ScratchDir dir;
    write_file(dir.file("abs.ldt"), ldt_text(1, 1, 3, "-4"));
    Photometry p = read_photometry(dir.file("abs.ldt"));
    EXPECT_TRUE(std::isnan(p.rated_lumens));
    EXPECT_EQ(p.lamp_count, 4);
    // The set's lumens are then the luminaire's flux, still the reference of cd/klm.
    EXPECT_EQ(p.candela[0], stored(0, 0) * 1.5);
}

TEST(EulumdatRoundTrip, FileLevelIsExactForEveryIsym) {
    ScratchDir dir;
    for (int isym = 0; isym <= 4; ++isym) {
        write_file(dir.file("s.ldt"), ldt_text(isym, 8, 5, "3", "1\nspare\n900\n4000 K\n1A\n10\n"));
        EulumdatFile a = read_eulumdat(dir.file("s.ldt"));
        write_eulumdat(dir.file("t.ldt"), a);
        EulumdatFile b = read_eulumdat(dir.file("t.ldt"));
        SCOPED_TRACE("Isym " + std::to_string(isym));
        EXPECT_EQ(b.isym, a.isym);
        EXPECT_EQ(b.c_angles_deg, a.c_angles_deg);
        EXPECT_EQ(b.intensities, a.intensities);
        EXPECT_EQ(b.direct_ratios, a.direct_ratios);
        EXPECT_EQ(b.luminous_height_mm, a.luminous_height_mm);
        EXPECT_EQ(b.lamp_sets[1].rendering, "1A");
        EXPECT_EQ(b.date_user, a.date_user);
    }
}

// LDT -> Photometry -> LDT and LDT -> IES -> LDT keep Isym, angles, lamp sets, the _LDT_ fields,
// and the intensities to rounding (cd/klm x lm / 1000 x 1000 / lm).
TEST(EulumdatRoundTrip, ThroughPhotometryAndIesForEveryIsym) {
    ScratchDir dir;
    for (int isym = 0; isym <= 4; ++isym) {
        write_file(dir.file("s.ldt"), ldt_text(isym, 8, 5, "3", "1\nspare\n900\n4000 K\n1A\n10\n"));
        EulumdatFile a = read_eulumdat(dir.file("s.ldt"));
        Photometry p = read_photometry(dir.file("s.ldt"));
        write_photometry(dir.file("x.ies"), p, PhotometryFormat::ies);
        write_photometry(dir.file("back.ldt"), read_photometry(dir.file("x.ies")),
                         PhotometryFormat::eulumdat);
        EulumdatFile b = read_eulumdat(dir.file("back.ldt"));
        SCOPED_TRACE("Isym " + std::to_string(isym));
        EXPECT_EQ(b.isym, isym == 1 ? 1 : a.isym);
        EXPECT_EQ(b.ityp, a.ityp);
        EXPECT_EQ(b.mc, isym == 1 ? 1 : a.mc);  // one plane needs one C angle
        if (isym != 1) {
            EXPECT_EQ(b.c_angles_deg, a.c_angles_deg);
        }
        EXPECT_EQ(b.gamma_angles_deg, a.gamma_angles_deg);
        ASSERT_EQ(b.intensities.size(), a.intensities.size());
        for (size_t i = 0; i < a.intensities.size(); ++i)
            EXPECT_NEAR(b.intensities[i], a.intensities[i], 1e-13 * a.intensities[i]);
        EXPECT_EQ(b.company, a.company);
        EXPECT_EQ(b.report_number, a.report_number);
        EXPECT_EQ(b.luminaire_name, a.luminaire_name);
        EXPECT_EQ(b.luminaire_number, a.luminaire_number);
        EXPECT_EQ(b.date_user, a.date_user);
        EXPECT_EQ(b.file_name, "back.ldt");
        EXPECT_EQ(b.downward_flux_percent, a.downward_flux_percent);
        EXPECT_EQ(b.light_output_ratio_percent, a.light_output_ratio_percent);
        EXPECT_EQ(b.direct_ratios, a.direct_ratios);
        EXPECT_EQ(b.luminaire_length_mm, a.luminaire_length_mm);
        for (size_t i = 0; i < 4; ++i)
            EXPECT_NEAR(b.luminous_height_mm[i], a.luminous_height_mm[i], 1e-12);
        EXPECT_NEAR(b.luminous_width_mm, a.luminous_width_mm, 1e-12);
        ASSERT_EQ(b.lamp_sets.size(), 2u);
        EXPECT_EQ(b.lamp_sets[0].count, 3);
        EXPECT_EQ(b.lamp_sets[0].lumens, 1500);
        EXPECT_EQ(b.lamp_sets[0].color, "3000 K");
        EXPECT_EQ(b.lamp_sets[0].watts, 22.5);
        EXPECT_EQ(b.lamp_sets[1].type, "spare");
    }
}

// IES -> LDT -> IES for every type C symmetry: the intensities everywhere, equal to rounding.
TEST(EulumdatRoundTrip, IesToLdtToIesForEverySymmetry) {
    ScratchDir dir;
    auto steps = [](double from, double to, double step) {
        std::vector<double> a;
        for (double x = from; x <= to + 1e-9; x += step) a.push_back(x);
        return a;
    };
    const std::vector<std::vector<double>> horizontals = {{0},
                                                          steps(0, 90, 15),
                                                          steps(0, 180, 22.5),
                                                          steps(90, 270, 15),
                                                          steps(0, 360, 30),
                                                          steps(0, 330, 30)};
    for (const auto& h : horizontals) {
        Photometry p;
        p.horizontal_deg = h;
        p.vertical_deg = steps(0, 180, 7.5);
        for (double a : h)
            for (double v :
                 p.vertical_deg)  // periodic in C: the C360 plane repeats C0, as LM-63 asks
                p.candela.push_back(1000.0 / 7 *
                                    (2 + std::sin(a * 3.14159265358979323846 / 180 + 0.05 * v)));
        p.rated_lumens = 4321;
        p.lamp_count = 2;
        p.keywords = {{"TEST", "T"}, {"MANUFAC", "M"}, {"LUMCAT", "C"}};
        SCOPED_TRACE(std::to_string(h.front()) + ".." + std::to_string(h.back()));
        write_photometry(dir.file("x.ies"), p, PhotometryFormat::ies);
        write_photometry(dir.file("x.ldt"), read_photometry(dir.file("x.ies")),
                         PhotometryFormat::eulumdat);
        write_photometry(dir.file("y.ies"), read_photometry(dir.file("x.ldt")),
                         PhotometryFormat::ies);
        Photometry q = read_photometry(dir.file("y.ies"));
        for (double c = 0; c < 360; c += 7.5)
            for (double v : p.vertical_deg)
                ASSERT_NEAR(q.intensity(c, v), p.intensity(c, v), 1e-13 * p.intensity(c, v))
                    << c << " " << v;
        EXPECT_EQ(q.rated_lumens, 4321);
        EXPECT_EQ(q.lamp_count, 2);
        EXPECT_EQ(q.keywords.at("LUMCAT"), "C");
    }
}

TEST(EulumdatWrite, DerivesDffLorlAndIsymWhenThePhotometryIsNotFromLdt) {
    // Isotropic 100 cd over the full sphere from a 1000 lm lamp: flux 400 pi lm, half of it below
    // the horizon; LORL = 400 pi / 1000. All 12 planes of the unfolded quadrant are equal: Isym 1.
    Photometry p;
    p.horizontal_deg = {0, 30, 60, 90};
    p.vertical_deg = {0, 45, 90, 135, 180};
    p.candela.assign(20, 100.0);
    p.rated_lumens = 1000;
    EulumdatFile f = eulumdat_from_photometry(p, "/somewhere/q.ldt");
    EXPECT_EQ(f.isym, 1);
    EXPECT_EQ(f.mc, 12);
    EXPECT_EQ(f.dc, 30);
    EXPECT_EQ(f.dg, 45);
    EXPECT_EQ(f.intensities.size(), 5u);
    EXPECT_EQ(f.file_name, "q.ldt");
    EXPECT_NEAR(f.downward_flux_percent, 50, 1e-12);
    EXPECT_NEAR(f.light_output_ratio_percent, 40 * 3.14159265358979323846, 1e-11);
    EXPECT_EQ(f.intensities[0], 100.0);  // cd/klm of 1000 lm
    // Planes that differ but mirror in both planes: Isym 4 with C0..C90 stored.
    p.candela[5] = 150;  // C30, gamma 0
    f = eulumdat_from_photometry(p, "q.ldt");
    EXPECT_EQ(f.isym, 4);
    EXPECT_EQ(f.intensities.size(), 20u);
    EXPECT_EQ(f.intensities[5], 150.0);
    // Absolute photometry: a negative count and the luminaire flux as the set's lumens.
    p.candela[5] = 100;
    p.rated_lumens = std::nan("");
    p.lamp_count = 2;
    f = eulumdat_from_photometry(p, "q.ldt");
    EXPECT_EQ(f.lamp_sets[0].count, -2);
    EXPECT_NEAR(f.lamp_sets[0].lumens, 400 * 3.14159265358979323846, 1e-9);
    EXPECT_EQ(f.light_output_ratio_percent, 100);
}

TEST(EulumdatWrite, MalformedLdtKeywordIsNamed) {
    Photometry p;
    p.horizontal_deg = {0};
    p.vertical_deg = {0, 90};
    p.candela = {10, 5};
    p.keywords["_LDT_LUMINOUS_HEIGHTS_MM"] = "1 2 x 4";
    try {
        eulumdat_from_photometry(p, "k.ldt");
        FAIL() << "a malformed _LDT_ keyword was written";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()),
                  "k.ldt: cannot write as EULUMDAT: keyword _LDT_LUMINOUS_HEIGHTS_MM is '1 2 x 4': "
                  "expected 4 numbers");
    }
}

TEST(EulumdatWrite, RefusesTypeB) {
    Photometry p;
    p.type = PhotometricType::B;
    p.horizontal_deg = {0, 90};
    p.vertical_deg = {-90, 90};
    p.candela.assign(4, 1.0);
    try {
        eulumdat_from_photometry(p, "out.ldt");
        FAIL() << "type B written as EULUMDAT";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("out.ldt: cannot write as EULUMDAT: it holds type C "
                                             "photometry only and this is type B"),
                  std::string::npos)
            << e.what();
    }
}

// ---- bad input -------------------------------------------------------------------------------

// Replaces line `n` (1-based) of text.
std::string with_line(const std::string& text, int n, const std::string& line) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string l; std::getline(in, l);) lines.push_back(l);
    lines.at(size_t(n - 1)) = line;
    std::string out;
    for (const auto& l : lines) out += l + "\n";
    return out;
}

TEST(EulumdatBadInput, MalformedNumberNamesTheLineAndField) {
    ScratchDir dir;
    write_file(dir.file("m.ldt"), with_line(ldt_text(0, 4, 3), 23, "8O"));
    std::string e = read_error(dir.file("m.ldt"));
    EXPECT_NE(
        e.find("m.ldt: line 23: expected LORL (light output ratio, %) (a number), found '8O'"),
        std::string::npos)
        << e;
}

TEST(EulumdatBadInput, TruncatedIntensities) {
    ScratchDir dir;
    std::string text = ldt_text(2, 8, 5);
    text.resize(text.rfind("\n", text.size() - 2) + 1);  // drop the last intensity line
    write_file(dir.file("t.ldt"), text);
    std::string e = read_error(dir.file("t.ldt"));
    // 42 header lines + 8 C angles + 5 gamma + 25 intensities: the 25th would be line 80.
    EXPECT_NE(e.find("t.ldt: line 80: file ends where intensity (cd/klm) #5 of 5 of stored C plane "
                     "#5 of 5 (Isym 2, Mc 8)"),
              std::string::npos)
        << e;
}

TEST(EulumdatBadInput, SymmetryCountsAndAngles) {
    ScratchDir dir;
    write_file(dir.file("i.ldt"), with_line(ldt_text(0, 4, 3), 3, "5"));
    EXPECT_NE(read_error(dir.file("i.ldt"))
                  .find("i.ldt: line 3: Isym (symmetry indicator) is 5: expected a whole number "
                        "from 0 to 4"),
              std::string::npos);
    write_file(dir.file("o.ldt"), with_line(ldt_text(4, 8, 3), 4, "6"));
    EXPECT_NE(
        read_error(dir.file("o.ldt")).find("o.ldt: line 4: Mc is 6: Isym 4 needs a multiple of 4"),
        std::string::npos);
    // C angle #5 (line 47) is where Isym 2 needs C180.
    write_file(dir.file("c.ldt"), with_line(ldt_text(2, 8, 3), 47, "170"));
    EXPECT_NE(read_error(dir.file("c.ldt"))
                  .find("c.ldt: line 3: Isym 2 needs C angle #5 to be 180 but it is 170"),
              std::string::npos);
    write_file(dir.file("a.ldt"), with_line(ldt_text(0, 4, 3), 45, "10"));
    EXPECT_NE(read_error(dir.file("a.ldt"))
                  .find("a.ldt: line 45: C angles are not ascending: 90 then 10"),
              std::string::npos);
    write_file(dir.file("x.ldt"), ldt_text(1, 1, 3) + "7\n");
    EXPECT_NE(read_error(dir.file("x.ldt"))
                  .find("x.ldt: line 50: unexpected '7' after the last intensity"),
              std::string::npos);
    write_file(dir.file("l.ldt"), with_line(ldt_text(1, 1, 3), 29, "0"));
    EXPECT_NE(
        read_error(dir.file("l.ldt"))
            .find("l.ldt: line 29: lamp set 1: flux is 0: expected a positive number of lumens"),
        std::string::npos);
    write_file(dir.file("b.ldt"), with_line(ldt_text(1, 1, 3), 6, "2000000000"));
    EXPECT_NE(read_error(dir.file("b.ldt"))
                  .find("b.ldt: line 7: Mc 1 and Ng 2000000000 ask for more values than the"),
              std::string::npos);
    write_file(dir.file("n.ldt"), with_line(ldt_text(1, 1, 3), 50 - 1, "inf"));
    EXPECT_NE(
        read_error(dir.file("n.ldt")).find("n.ldt: line 49: expected intensity (cd/klm) #3 of 3"),
        std::string::npos);
}

TEST(PhotometryDetect, ByContent) {
    ScratchDir dir;
    write_file(dir.file("a.txt"), ldt_text(1, 1, 3));
    EXPECT_EQ(detect_photometry_format(dir.file("a.txt")), PhotometryFormat::eulumdat);
    write_file(dir.file("b.txt"),
               "OLD 1986 LABEL\n  TILT=NONE\n1 -1 1 1 1 1 2 0 0 0\n1 1 0\n0\n0\n5\n");
    EXPECT_EQ(detect_photometry_format(dir.file("b.txt")), PhotometryFormat::ies);
    EXPECT_EQ(read_photometry(dir.file("b.txt")).candela, std::vector<double>{5});
    // EULUMDAT text lines may hold anything, even what looks like an IES TILT line.
    write_file(dir.file("t.txt"), with_line(ldt_text(1, 1, 3), 9, "TILT=INCLUDE fixture"));
    EXPECT_EQ(detect_photometry_format(dir.file("t.txt")), PhotometryFormat::eulumdat);
    write_file(dir.file("c.txt"), "hello\nworld\n");
    try {
        detect_photometry_format(dir.file("c.txt"));
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("c.txt: neither an IES LM-63 file"), std::string::npos)
            << e.what();
    }
}

}  // namespace
}  // namespace rayset
