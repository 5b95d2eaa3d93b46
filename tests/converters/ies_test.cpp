// IES LM-63: hand-written files of every version and TILT form, round trips for every
// symmetry, and every kind of bad input with the message it must give.
#include "converters/photometry/ies.h"
#include "converters/photometry/photometry.h"
#include "core/error.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <cmath>

namespace rayset {
namespace {

using test::ScratchDir;
using test::write_file;

// The message of the Error reading `path` throws; fails the test if nothing is thrown.
std::string read_error(const std::string& path) {
    try {
        read_ies(path);
    } catch (const Error& e) {
        return e.what();
    }
    ADD_FAILURE() << "no error reading " << path;
    return {};
}

const char* const small_2002 =
    "IESNA:LM-63-2002\r\n"
    "[TEST] T-1\r\n"
    "[MANUFAC] Maker\r\n"
    "[LUMINAIRE] first line\r\n"
    "[MORE] second line\r\n"
    "[_CUSTOM] x\r\n"
    "[OTHER] one\r\n"
    "[OTHER] two\r\n"
    "TILT=NONE\r\n"
    "2 500 1.5 3 2 1 1\r\n"  // numbers wrap anywhere:
    "1 -2 0.5\r\n"           // width 1 ft, length -2 ft (round), height 0.5 ft
    "0.9 1 42\r\n"
    "0 45\r\n90\r\n"
    "0 90\r\n"
    "10 20 30\r\n40 50\r\n60\r\n";

TEST(IesRead, HeaderKeywordsNumbersAndUnits) {
    ScratchDir dir;
    write_file(dir.file("a.ies"), small_2002);
    IesFile f = read_ies(dir.file("a.ies"));
    EXPECT_EQ(f.version, IesVersion::lm63_2002);
    ASSERT_EQ(f.keywords.size(), 6u);
    EXPECT_EQ(f.keywords[2].key, "LUMINAIRE");
    EXPECT_EQ(f.keywords[2].value, "first line\nsecond line");
    EXPECT_EQ(f.keywords[3].key, "_CUSTOM");
    EXPECT_EQ(f.keywords[5].value, "two");
    EXPECT_EQ(f.lamp_count, 2);
    EXPECT_EQ(f.lumens_per_lamp, 500);
    EXPECT_EQ(f.multiplier, 1.5);
    EXPECT_EQ(f.ballast_factor, 0.9);
    EXPECT_EQ(f.input_watts, 42);
    EXPECT_EQ(f.vertical_deg, (std::vector<double>{0, 45, 90}));
    EXPECT_EQ(f.horizontal_deg, (std::vector<double>{0, 90}));
    EXPECT_EQ(f.candela, (std::vector<double>{10, 20, 30, 40, 50, 60}));

    Photometry p = ies_to_photometry(f);
    // The multiplier is applied once; the ballast factor is kept apart.
    EXPECT_EQ(p.candela, (std::vector<double>{15, 30, 45, 60, 75, 90}));
    EXPECT_EQ(p.ballast_factor, 0.9);
    EXPECT_EQ(p.rated_lumens, 1000);
    EXPECT_EQ(p.width_m, 0.3048);
    EXPECT_EQ(p.length_m, 2 * 0.3048);
    EXPECT_EQ(p.height_m, 0.5 * 0.3048);
    EXPECT_TRUE(p.round);
    EXPECT_EQ(p.keywords.at("LUMINAIRE"), "first line\nsecond line");
    EXPECT_EQ(p.keywords.at("OTHER"), "one\ntwo");  // repeated keywords joined in file order
    EXPECT_EQ(p.keywords.at("_CUSTOM"), "x");
}

TEST(IesRead, EveryVersionLine) {
    ScratchDir dir;
    const std::string body = "TILT=NONE\n1 -1 1 1 1 1 2 0 0 0\n1 1 0\n0\n0\n5\n";
    struct Case {
        const char* first;
        IesVersion version;
    } cases[] = {{"IESNA91\n[TEST] x\n", IesVersion::lm63_1991},
                 {"IESNA:LM-63-1995\n[TEST] x\n", IesVersion::lm63_1995},
                 {"IESNA:LM-63-2002\n[TEST] x\n", IesVersion::lm63_2002},
                 {"IES:LM-63-2019\n[TEST] x\n", IesVersion::lm63_2019},
                 {"FREE TEXT OF A 1986 FILE\nSECOND LINE\n", IesVersion::lm63_1986}};
    for (const auto& c : cases) {
        write_file(dir.file("v.ies"), std::string(c.first) + body);
        IesFile f = read_ies(dir.file("v.ies"));
        EXPECT_EQ(f.version, c.version) << c.first;
        EXPECT_TRUE(std::isnan(ies_to_photometry(f).rated_lumens))
            << "lumens -1 is absolute photometry";
        EXPECT_EQ(ies_to_photometry(f).candela, std::vector<double>{5});
    }
    IesFile f1986 = read_ies(dir.file("v.ies"));
    ASSERT_EQ(f1986.keywords.size(), 2u);
    EXPECT_EQ(f1986.keywords[0].key, "");
    EXPECT_EQ(ies_to_photometry(f1986).keywords.at("OTHER"),
              "FREE TEXT OF A 1986 FILE\nSECOND LINE");
}

TEST(IesRead, ByteOrderMarkAndDosEndOfFileMark) {
    ScratchDir dir;
    write_file(dir.file("b.ies"),
               "\xEF\xBB\xBFIESNA:LM-63-2002\r\nTILT=NONE\r\n1 -1 1 1 1 1 2 0 0 0\r\n1 1 "
               "0\r\n0\r\n0\r\n5\r\n\x1a");
    EXPECT_EQ(detect_photometry_format(dir.file("b.ies")), PhotometryFormat::ies);
    IesFile f = read_ies(dir.file("b.ies"));
    EXPECT_EQ(f.version, IesVersion::lm63_2002);
    EXPECT_TRUE(f.keywords.empty());
    EXPECT_EQ(f.candela, std::vector<double>{5});
}

TEST(IesRead, TiltIncludeAndTiltFile) {
    ScratchDir dir;
    const std::string numbers = "1 1000 1 2 1 1 2 0 0 0\n1 1 10\n0 90\n0\n100 50\n";
    write_file(dir.file("inc.ies"),
               "IESNA:LM-63-2002\nTILT=INCLUDE\n2\n3\n0 45 90\n1 0.95\n0.9\n" + numbers);
    IesFile inc = read_ies(dir.file("inc.ies"));
    EXPECT_EQ(inc.tilt.kind, IesTilt::Kind::include);
    EXPECT_EQ(inc.tilt.lamp_to_luminaire_geometry, 2);
    EXPECT_EQ(inc.tilt.angles_deg, (std::vector<double>{0, 45, 90}));
    EXPECT_EQ(inc.tilt.multipliers, (std::vector<double>{1, 0.95, 0.9}));
    EXPECT_EQ(inc.candela, (std::vector<double>{100, 50}));

    write_file(dir.file("lamp.tlt"), "3\n2\n0 180\n1 0.5\n");
    write_file(dir.file("ref.ies"), "IESNA:LM-63-1995\nTILT=lamp.tlt\n" + numbers);
    IesFile ref = read_ies(dir.file("ref.ies"));
    EXPECT_EQ(ref.tilt.kind, IesTilt::Kind::file);
    EXPECT_EQ(ref.tilt.file_name, "lamp.tlt");
    EXPECT_EQ(ref.tilt.lamp_to_luminaire_geometry, 3);
    EXPECT_EQ(ref.tilt.multipliers, (std::vector<double>{1, 0.5}));

    // Written and read again, the TILT data is unchanged.
    write_ies(dir.file("inc2.ies"), inc);
    IesFile again = read_ies(dir.file("inc2.ies"));
    EXPECT_EQ(again.tilt.lamp_to_luminaire_geometry, 2);
    EXPECT_EQ(again.tilt.angles_deg, inc.tilt.angles_deg);
    EXPECT_EQ(again.tilt.multipliers, inc.tilt.multipliers);
}

// ---- round trips -----------------------------------------------------------------------------

std::vector<double> steps(double from, double to, double step) {
    std::vector<double> a;
    for (int i = 0; i <= int(std::lround((to - from) / step)); ++i) a.push_back(from + i * step);
    return a;
}

// Values with all 17 significant digits, different for every cell.
Photometry sample(PhotometricType type, std::vector<double> h, std::vector<double> v) {
    Photometry p;
    p.type = type;
    p.horizontal_deg = std::move(h);
    p.vertical_deg = std::move(v);
    for (double a : p.horizontal_deg)
        for (double b : p.vertical_deg)
            p.candela.push_back(1000.0 / 3 * (1.5 + std::sin(0.05 * a + 0.021 * b)));
    p.lamp_count = 3;
    p.rated_lumens = 3 * 1234.5;
    p.input_watts = 17.3;
    p.ballast_factor = 0.95;
    p.width_m = 0.1 / 3;
    p.length_m = 0.25;
    p.height_m = 0.07;
    p.keywords = {
        {"TEST", "R-1"}, {"MANUFAC", "Maker\nsecond line"}, {"_Z", "last"}, {"LAMP", "LED"}};
    return p;
}

void expect_same(const Photometry& a, const Photometry& b) {
    EXPECT_EQ(a.type, b.type);
    EXPECT_EQ(a.horizontal_deg, b.horizontal_deg);
    EXPECT_EQ(a.vertical_deg, b.vertical_deg);
    EXPECT_EQ(a.candela, b.candela);
    EXPECT_EQ(a.lamp_count, b.lamp_count);
    EXPECT_EQ(a.rated_lumens, b.rated_lumens);
    EXPECT_EQ(a.input_watts, b.input_watts);
    EXPECT_EQ(a.ballast_factor, b.ballast_factor);
    EXPECT_EQ(a.width_m, b.width_m);
    EXPECT_EQ(a.length_m, b.length_m);
    EXPECT_EQ(a.height_m, b.height_m);
    EXPECT_EQ(a.round, b.round);
    EXPECT_EQ(a.keywords, b.keywords);
}

TEST(IesRoundTrip, EverySymmetryIsExactInValue) {
    ScratchDir dir;
    const std::vector<std::pair<std::string, Photometry>> cases = {
        {"axial", sample(PhotometricType::C, {0}, steps(0, 180, 2.5))},
        {"quadrant", sample(PhotometricType::C, {0, 5, 15, 25, 35, 45, 46, 55, 65, 75, 85, 90},
                            steps(0, 90, 5))},
        {"bilateral", sample(PhotometricType::C, steps(0, 180, 22.5), steps(90, 180, 10))},
        {"none", sample(PhotometricType::C, steps(0, 360, 15), steps(0, 180, 5))},
        {"type B", sample(PhotometricType::B, steps(0, 90, 10), steps(-90, 90, 5))},
        {"type A", sample(PhotometricType::A, steps(-90, 90, 10), steps(-90, 90, 10))}};
    for (auto version : {IesVersion::lm63_2002, IesVersion::lm63_2019}) {
        for (const auto& [name, p] : cases) {
            write_photometry(dir.file("p.ies"), p, PhotometryFormat::ies);
            if (version == IesVersion::lm63_2019)
                write_ies(dir.file("p.ies"), ies_from_photometry(p, "p.ies", version));
            Photometry back = read_photometry(dir.file("p.ies"));
            SCOPED_TRACE(name);
            if (version == IesVersion::lm63_2019) {
                // 2019 requires TEST, TESTLAB, ISSUEDATE and MANUFAC: the missing ones come back
                // empty.
                EXPECT_EQ(back.keywords.at("TESTLAB"), "");
                back.keywords.erase("TESTLAB");
                back.keywords.erase("ISSUEDATE");
            }
            expect_same(p, back);
        }
    }
    // Absolute photometry stays absolute.
    Photometry absolute = cases[0].second;
    absolute.rated_lumens = std::nan("");
    write_photometry(dir.file("abs.ies"), absolute, PhotometryFormat::ies);
    EXPECT_EQ(read_ies(dir.file("abs.ies")).lumens_per_lamp, -1);
    EXPECT_TRUE(std::isnan(read_photometry(dir.file("abs.ies")).rated_lumens));
}

TEST(IesRoundTrip, Bilateral90To270IsUnfoldedFor2002AndKeptFor1995) {
    ScratchDir dir;
    Photometry p = sample(PhotometricType::C, steps(90, 270, 15), steps(0, 180, 10));
    write_photometry(dir.file("b.ies"), p, PhotometryFormat::ies);
    Photometry back = read_photometry(dir.file("b.ies"));
    EXPECT_EQ(back.horizontal_deg, steps(0, 360, 15));
    for (double c = 0; c < 360; c += 7.5)
        for (double g = 0; g <= 180; g += 5)
            ASSERT_EQ(back.intensity(c, g), p.intensity(c, g)) << c << " " << g;
    EXPECT_NEAR(back.total_flux(), p.total_flux(), 1e-12 * p.total_flux());

    write_ies(dir.file("b95.ies"), ies_from_photometry(p, "b95.ies", IesVersion::lm63_1995));
    expect_same(p, read_photometry(dir.file("b95.ies")));
}

TEST(IesRoundTrip, FileLevelKeepsOrderTiltUnitsAndMultiplier) {
    ScratchDir dir;
    write_file(dir.file("a.ies"), small_2002);
    IesFile f = read_ies(dir.file("a.ies"));
    write_ies(dir.file("b.ies"), f);
    IesFile g = read_ies(dir.file("b.ies"));
    ASSERT_EQ(g.keywords.size(), f.keywords.size());
    for (size_t i = 0; i < f.keywords.size(); ++i) {
        EXPECT_EQ(g.keywords[i].key, f.keywords[i].key);
        EXPECT_EQ(g.keywords[i].value, f.keywords[i].value);
    }
    EXPECT_EQ(g.units, 1);
    EXPECT_EQ(g.multiplier, 1.5);
    EXPECT_EQ(g.length, -2);
    EXPECT_EQ(g.candela, f.candela);
    // Lines stay within 80 columns however many values there are.
    Photometry wide = sample(PhotometricType::C, {0}, steps(0, 180, 0.5));
    write_photometry(dir.file("w.ies"), wide, PhotometryFormat::ies);
    std::string text = test::read_file(dir.file("w.ies"));
    size_t start = 0, longest = 0;
    for (size_t end; (end = text.find("\r\n", start)) != std::string::npos; start = end + 2)
        longest = std::max(longest, end - start);
    EXPECT_LE(longest, 80u);
    EXPECT_GT(longest, 60u);
}

// ---- bad input -------------------------------------------------------------------------------

std::string with_numbers(const std::string& numbers) {
    return "IESNA:LM-63-2002\n[TEST] x\nTILT=NONE\n" + numbers;
}

TEST(IesBadInput, MalformedNumberNamesTheLine) {
    ScratchDir dir;
    write_file(dir.file("m.ies"),
               with_numbers("1 -1 1 3 1 1 2 0 0 0\n1 1 0\n0 45 90\n0\n10 2O 30\n"));
    std::string e = read_error(dir.file("m.ies"));
    EXPECT_NE(e.find("m.ies: line 8: expected candela value #2 of 3 for horizontal angle 0"),
              std::string::npos)
        << e;
    EXPECT_NE(e.find("found '2O'"), std::string::npos) << e;
}

TEST(IesBadInput, TooFewCandelaValues) {
    ScratchDir dir;
    write_file(dir.file("few.ies"),
               with_numbers("1 -1 1 3 2 1 2 0 0 0\n1 1 0\n0 45 90\n0 90\n1 2 3\n4 5\n"));
    std::string e = read_error(dir.file("few.ies"));
    EXPECT_NE(
        e.find("few.ies: line 9: file ends where candela value #3 of 3 for horizontal angle 90"),
        std::string::npos)
        << e;
    EXPECT_NE(e.find("the counts on line 4 ask for 3 x 2"), std::string::npos) << e;
}

TEST(IesBadInput, TooManyValuesMeansTheCountsAreWrong) {
    ScratchDir dir;
    write_file(dir.file("many.ies"), with_numbers("1 -1 1 2 1 1 2 0 0 0\n1 1 0\n0 90\n0\n1 2 3\n"));
    std::string e = read_error(dir.file("many.ies"));
    EXPECT_NE(e.find("many.ies: line 8: unexpected '3' after the last of the 2 candela values"),
              std::string::npos)
        << e;
}

TEST(IesBadInput, UnknownPhotometricTypeAndUnits) {
    ScratchDir dir;
    write_file(dir.file("t.ies"), with_numbers("1 -1 1 1 1 4 2 0 0 0\n1 1 0\n0\n0\n5\n"));
    std::string e = read_error(dir.file("t.ies"));
    EXPECT_NE(e.find("t.ies: line 4: unknown photometric type 4: expected 1 (type C), 2 (type B) "
                     "or 3 (type A)"),
              std::string::npos)
        << e;
    write_file(dir.file("u.ies"), with_numbers("1 -1 1 1 1 1 3 0 0 0\n1 1 0\n0\n0\n5\n"));
    e = read_error(dir.file("u.ies"));
    EXPECT_NE(e.find("u.ies: line 4: units type is 3: expected 1 (feet) or 2 (metres)"),
              std::string::npos)
        << e;
}

TEST(IesBadInput, MissingTiltFileIsNamed) {
    ScratchDir dir;
    write_file(dir.file("t.ies"),
               "IESNA:LM-63-1995\n[TEST] x\nTILT=lamp.tlt\n1 -1 1 1 1 1 2 0 0 0\n1 1 0\n0\n0\n5\n");
    std::string e = read_error(dir.file("t.ies"));
    EXPECT_NE(e.find("t.ies: line 3: TILT file 'lamp.tlt' not found (looked for " +
                     dir.file("lamp.tlt") + ")"),
              std::string::npos)
        << e;
}

TEST(IesBadInput, AnglesNotAscendingAndOutOfRange) {
    ScratchDir dir;
    write_file(dir.file("a.ies"), with_numbers("1 -1 1 3 1 1 2 0 0 0\n1 1 0\n0 50 45\n0\n1 2 3\n"));
    std::string e = read_error(dir.file("a.ies"));
    EXPECT_NE(e.find("a.ies: line 6: vertical angles are not ascending: 50 then 45"),
              std::string::npos)
        << e;
    write_file(dir.file("r.ies"), with_numbers("1 -1 1 2 1 1 2 0 0 0\n1 1 0\n0 190\n0\n1 2\n"));
    e = read_error(dir.file("r.ies"));
    EXPECT_NE(e.find("r.ies: line 6: vertical angle #2 is 190: expected 0 to 180 degrees"),
              std::string::npos)
        << e;
    write_file(dir.file("h.ies"), with_numbers("1 -1 1 1 2 1 2 0 0 0\n1 1 0\n0\n0 45\n1 2\n"));
    e = read_error(dir.file("h.ies"));
    EXPECT_NE(e.find("h.ies: line 7: type C horizontal angles run 0..45"), std::string::npos) << e;
}

TEST(IesBadInput, HeaderProblems) {
    ScratchDir dir;
    write_file(dir.file("v.ies"), "IESNA:LM-63-2024\nTILT=NONE\n");
    EXPECT_NE(read_error(dir.file("v.ies"))
                  .find("v.ies: line 1: unknown version line 'IESNA:LM-63-2024'"),
              std::string::npos);
    write_file(dir.file("m.ies"), "IESNA:LM-63-2002\n[MORE] nothing before\nTILT=NONE\n");
    EXPECT_NE(read_error(dir.file("m.ies")).find("m.ies: line 2: [MORE] with no keyword before it"),
              std::string::npos);
    write_file(dir.file("n.ies"), "IESNA:LM-63-2002\n[TEST] x\n1 2 3\n");
    EXPECT_NE(read_error(dir.file("n.ies")).find("n.ies: line 3: file ends before the TILT= line"),
              std::string::npos);
    write_file(dir.file("g.ies"), "IESNA:LM-63-2002\nTILT=INCLUDE\n7\n");
    EXPECT_NE(read_error(dir.file("g.ies"))
                  .find("g.ies: line 3: TILT lamp-to-luminaire geometry (1, 2 or 3) is 7"),
              std::string::npos);
}

TEST(IesBadInput, NonFiniteNegativeAndImpossibleCounts) {
    ScratchDir dir;
    write_file(dir.file("nan.ies"), with_numbers("1 -1 1 2 1 1 2 0 0 0\n1 1 0\n0 90\n0\n1 nan\n"));
    EXPECT_NE(read_error(dir.file("nan.ies"))
                  .find("nan.ies: line 8: candela value #2 of 2 for horizontal angle 0"),
              std::string::npos);
    EXPECT_NE(read_error(dir.file("nan.ies")).find("is nan: expected a finite number"),
              std::string::npos);
    write_file(dir.file("neg.ies"), with_numbers("1 -1 1 2 1 1 2 0 0 0\n1 1 0\n0 90\n0\n1 -4\n"));
    EXPECT_NE(read_error(dir.file("neg.ies")).find("neg.ies: line 8: candela value -4 is negative"),
              std::string::npos);
    write_file(dir.file("big.ies"), with_numbers("1 -1 1 100000 100000 1 2 0 0 0\n1 1 0\n0\n"));
    std::string e = read_error(dir.file("big.ies"));
    EXPECT_NE(e.find("big.ies: line 5: the angle counts (line 4) ask for 10000200000 numbers but "
                     "the file has only"),
              std::string::npos)
        << e;
    write_file(dir.file("lm.ies"), with_numbers("1 0 1 1 1 1 2 0 0 0\n1 1 0\n0\n0\n5\n"));
    EXPECT_NE(
        read_error(dir.file("lm.ies"))
            .find(
                "lumens per lamp is 0: expected a positive number, or -1 for absolute photometry"),
        std::string::npos);
}

TEST(IesWrite, RefusesWhatLm63CannotHold) {
    ScratchDir dir;
    Photometry p = sample(PhotometricType::C, {0, 45}, {0, 90});
    try {
        write_photometry(dir.file("x.ies"), p, PhotometryFormat::ies);
        FAIL() << "type C 0..45 written";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(
                      "x.ies: cannot write as IES: type C horizontal angles run 0..45"),
                  std::string::npos)
            << e.what();
    }
    EXPECT_FALSE(std::filesystem::exists(dir.file("x.ies")));
}

}  // namespace
}  // namespace rayset
