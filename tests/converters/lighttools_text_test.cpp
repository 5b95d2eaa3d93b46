// LightTools text ray data on hand-made files: bit-exact round trips, identity with the binary
// format, format detection, and every bad-input message (file, line and column).
#include "lighttools_test_support.h"

namespace rayset {
namespace {

using namespace lighttools_test;
using test::ScratchDir;
using test::write_file;

TEST(LightToolsText, RoundTripIsBitExact) {
    ScratchDir dir;
    const std::string path = dir.file("rt.txt");
    const std::vector<Ray> rays = make_rays(57, true, false);
    RayHeader h = make_header(true, false, LengthUnit::um);
    h.stated_radiant = 7.25;
    auto e = create_lighttools_text(path, h);
    write_rays(*e, rays);
    EXPECT_TRUE(e->dropped().empty());
    auto d = open_lighttools_text(path);
    const RayHeader& r = d->header();
    EXPECT_TRUE(d->flux_is_relative());
    EXPECT_EQ(r.format, RayFormat::lighttools_text);
    EXPECT_EQ(r.ray_count, 57u);
    EXPECT_EQ(r.unit, LengthUnit::um);
    EXPECT_EQ(r.data_origin, h.data_origin);
    EXPECT_EQ(r.text[0], "testRays");
    // The writer adds the identifying first line because the description lacks it.
    EXPECT_EQ(r.description, "LightTools ray data written by rayset\n" + h.description);
    double sum = 0;
    for (const Ray& ray : rays) sum += ray.radiant;
    EXPECT_EQ(r.stated_radiant, sum);  // 7.25 disagrees with the rays: their sum is written
    expect_same_rays(rays, read_all(*d, 10));
}

TEST(LightToolsText, BinaryAndTextGiveIdenticalRays) {
    ScratchDir dir;
    const std::vector<Ray> rays = make_rays(33, false, true);
    RayHeader h = make_header(false, true, LengthUnit::m);
    h.stated_luminous = 1000;
    write_rays(*create_lighttools_binary(dir.file("a.ray"), h), rays);
    write_rays(*create_lighttools_text(dir.file("a.txt"), h), rays);
    auto b = open_lighttools_binary(dir.file("a.ray"));
    auto t = open_lighttools_text(dir.file("a.txt"));
    EXPECT_EQ(b->header().unit, t->header().unit);
    EXPECT_EQ(b->header().has_luminous, t->header().has_luminous);
    EXPECT_EQ(float(b->header().stated_luminous), float(t->header().stated_luminous));
    expect_same_rays(read_all(*b), read_all(*t));
}

TEST(LightToolsText, ReadsHandWrittenFileWithBlankLinesAndLf) {
    ScratchDir dir;
    const std::string path = dir.file("hand.txt");
    write_file(path,
               "# LightTools 9\n# note\nlt_rdf_version: 2.0\nlt_datatype: "
               "luminous_flux\nlt_far_field_data: no\n"
               "lt_color_info: none\nlt_length_units: inches\nlt_data_origin: 1 2 "
               "3\nlt_luminous_flux: 50\n"
               "lt_startofdata\n1 2 3 0 0 1 2\n\n  -1 -2 -3 0 1 0 3e-016  \nlt_endofdata\n\n");
    auto d = open_lighttools_text(path);
    const RayHeader& h = d->header();
    EXPECT_EQ(h.ray_count, 2u);
    EXPECT_EQ(h.unit, LengthUnit::inch);
    EXPECT_EQ(h.stated_luminous, 50);
    EXPECT_EQ(h.data_origin, (Vec3f{1, 2, 3}));
    EXPECT_EQ(h.description, "LightTools 9\nnote");
    std::vector<Ray> rays = read_all(*d);
    ASSERT_EQ(rays.size(), 2u);
    EXPECT_EQ(rays[1].origin, (Vec3f{-1, -2, -3}));
    EXPECT_EQ(rays[1].luminous, 3e-16f);
    EXPECT_EQ(d->locate(1).str(), "line 13");
}

const char* kTextHeader =
    "# LightTools 2024.03 \r\n# Ray Data Export File\r\nlt_rdf_version: 2.0\r\ndataname: x\r\n"
    "lt_datatype: radiant_power\r\nlt_far_field_data: no\r\nlt_color_info: wavelength\r\n"
    "lt_length_units: millimeters\r\nlt_data_origin: 0 0 0\r\nlt_radiant_flux: "
    "0.5\r\nlt_startofdata\r\n";
const char* kTextRow = "  0.1 0.2 0.3 0 0 1 0.25 550\r\n";  // line 12

TEST(LightToolsTextErrors, Truncated) {
    ScratchDir dir;
    const std::string path = dir.file("cut.txt");
    write_file(path, std::string(kTextHeader) + kTextRow + kTextRow + "  0.1 0.2 0.");
    expect_open_error(open_lighttools_text, path,
                      {"line 14:", "ends without lt_endofdata", "truncated"});
}

TEST(LightToolsTextErrors, RowWithSixNumbers) {
    ScratchDir dir;
    const std::string path = dir.file("six.txt");
    write_file(path, std::string(kTextHeader) + kTextRow + "1 2 3 0 0 1\r\nlt_endofdata\r\n");
    expect_open_error(open_lighttools_text, path, {"line 13:", "expected 8 numbers", "found 6"});
}

TEST(LightToolsTextErrors, NotANumber) {
    ScratchDir dir;
    const std::string path = dir.file("abc.txt");
    write_file(path, std::string(kTextHeader) + kTextRow + kTextRow +
                         "1 2 abc 0 0 1 1 500\r\nlt_endofdata\r\n");
    expect_open_error(open_lighttools_text, path, {"line 14, column 5:", "'abc' is not a number"});
}

TEST(LightToolsTextErrors, MissingStartOfData) {
    ScratchDir dir;
    std::string header = kTextHeader;
    header.erase(header.find("lt_startofdata"));
    const std::string path = dir.file("nostart.txt");
    write_file(path, header + kTextRow + "lt_endofdata\r\n");
    expect_open_error(
        open_lighttools_text, path,
        {"line 11:", "expected 'key: value' or lt_startofdata", "is lt_startofdata missing?"});
    write_file(path, header);
    expect_open_error(open_lighttools_text, path,
                      {"line 10:", "ends inside the header, before lt_startofdata", "truncated"});
    write_file(path, header.substr(0, header.find("lt_datatype") + 5));
    expect_open_error(open_lighttools_text, path,
                      {"line 5:", "ends inside the header", "truncated"});
}

TEST(LightToolsTextErrors, BadKeys) {
    ScratchDir dir;
    const std::string path = dir.file("keys.txt");
    auto with = [&](const std::string& from, const std::string& to) {
        std::string text = std::string(kTextHeader) + kTextRow + "lt_endofdata\r\n";
        text.replace(text.find(from), from.size(), to);
        write_file(path, text);
    };
    with("radiant_power", "joules");
    expect_open_error(open_lighttools_text, path,
                      {"line 5, column 14:", "unknown lt_datatype 'joules'"});
    with("millimeters", "furlongs");
    expect_open_error(open_lighttools_text, path,
                      {"line 8, column 18:", "unknown lt_length_units 'furlongs'"});
    with("lt_far_field_data: no", "lt_far_field_data: yes");
    expect_open_error(open_lighttools_text, path,
                      {"line 6, column 20:", "far-field", "not supported"});
    with("lt_color_info: wavelength", "lt_color_info: tristimulus");
    expect_open_error(open_lighttools_text, path,
                      {"line 7, column 16:", "'tristimulus' is not supported"});
    with("lt_radiant_flux: 0.5", "lt_radiant_flux: lots");
    expect_open_error(
        open_lighttools_text, path,
        {"line 10, column 18:", "lt_radiant_flux 'lots' is not a non-negative number"});
    with("lt_radiant_flux: 0.5\r\n", "");
    expect_open_error(open_lighttools_text, path,
                      {"line 10:",
                       "no lt_radiant_flux line before lt_startofdata: the relative ray fluxes "
                       "cannot be scaled"});
    with("lt_rdf_version: 2.0", "lt_rdf_version: 3.0");
    expect_open_error(open_lighttools_text, path, {"line 3, column 17:", "'3.0' is not supported"});
    with("dataname: x", "lt_polarization: yes");
    expect_open_error(open_lighttools_text, path, {"line 4:", "unknown key lt_polarization"});
    with("dataname: x", "lt_datatype: radiant_power");
    expect_open_error(open_lighttools_text, path,
                      {"line 5:", "lt_datatype is given a second time (first on line 4)"});
    with("lt_endofdata", "lt_endofdata\r\n0 0 0 0 0 1 1 500");
    expect_open_error(open_lighttools_text, path,
                      {"line 14:", "unexpected text after lt_endofdata"});
}

// ---------------------------------------------------------------------------------------------
Head head_of(const std::string& text) { return Head(text.begin(), text.end()); }

TEST(LightToolsSniff, RecognisesOwnFormatsOnly) {
    const std::string binary = binary_file(0, 0, 0, 1, 1, kTwoRays7);
    EXPECT_TRUE(sniff_lighttools_binary(head_of(binary), binary.size()));
    EXPECT_FALSE(sniff_lighttools_text(head_of(binary), binary.size()));
    EXPECT_TRUE(sniff_lighttools_text(head_of(kTextHeader), 100));
    EXPECT_TRUE(sniff_lighttools_text(head_of("\xEF\xBB\xBFlt_rdf_version: 2.0\n"), 100));
    EXPECT_FALSE(sniff_lighttools_binary(head_of(kTextHeader), 100));
    EXPECT_FALSE(sniff_lighttools_text(head_of("TM25\xdd\x07"), 100));
    EXPECT_FALSE(sniff_lighttools_binary(head_of("LTR"), 3));
}

}  // namespace
}  // namespace rayset
