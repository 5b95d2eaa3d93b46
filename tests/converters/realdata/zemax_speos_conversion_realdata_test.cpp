// Converting the ansys/optical-automation test files with rayset reproduces that project's own
// conversions (test_08_*_reference.*): the same rays carrying the same absolute flux. Both sides
// are read through the validating reader, which scales relative fluxes to the stated totals;
// rayset states totals that agree with the rays it writes, optical-automation keeps the
// relative weights, so only the absolute fluxes are comparable.
#include "converters/formats/codecs.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

namespace rayset {
namespace {

std::string rayfile(const std::string& name) { return test::shared_data("rayfiles/" + name); }

std::vector<Ray> read_all(RayReader& reader) {
    std::vector<Ray> rays;
    RayChunk chunk;
    while (reader.read(chunk)) rays.insert(rays.end(), chunk.rays.begin(), chunk.rays.end());
    return rays;
}

std::string convert(const test::ScratchDir& dir, const std::string& from, RayFormat to,
                    const std::vector<std::string>& dropped = {}) {
    auto in = open_rays(rayfile(from));
    const std::string out = dir.file("converted");
    auto encoder = create_rays(out, to, in->header());
    copy_rays(*in, *encoder);
    EXPECT_EQ(encoder->dropped(), dropped);
    return out;
}

// Positions, directions and wavelengths equal; absolute fluxes within the f32 rounding of a
// scale by 1/11 applied twice (2 x 6e-8, bound 1e-6).
void expect_same_rays(const std::string& ours, const std::string& theirs) {
    auto a = open_rays(ours), b = open_rays(theirs);
    const auto x = read_all(*a), y = read_all(*b);
    ASSERT_EQ(x.size(), 11u);
    ASSERT_EQ(x.size(), y.size());
    for (size_t i = 0; i < x.size(); ++i) {
        SCOPED_TRACE("ray " + std::to_string(i + 1));
        EXPECT_EQ(x[i].origin, y[i].origin);
        EXPECT_EQ(x[i].direction, y[i].direction);
        EXPECT_EQ(x[i].wavelength, y[i].wavelength);
        EXPECT_NEAR(x[i].radiant, y[i].radiant, 1e-6 * y[i].radiant);
    }
    EXPECT_NEAR(a->totals().radiant, b->totals().radiant, 1e-6 * b->totals().radiant);
}

float header_float(const std::string& path, size_t offset) {
    const std::string bytes = test::read_file(path);
    float v;
    std::memcpy(&v, &bytes.at(offset), 4);
    return v;
}

// 550 nm from the DAT header becomes every SPEOS ray's wavelength; the luminous total is 1 W
// through V(550 nm): optical-automation states 679.551 lm with 683 lm/W, rayset 683.002 lm/W
// (2.9e-6 relative above), so 5e-6.
TEST(ZemaxSpeosConversion, DatToSpeosMatchesTheReferenceConversion) {
    RAYSET_REQUIRE_SHARED_DATA();
    test::ScratchDir dir;
    const std::string ours = convert(dir, "test_08_dat.DAT", RayFormat::speos);
    const std::string theirs = rayfile("test_08_dat_reference.ray");
    expect_same_rays(ours, theirs);
    EXPECT_EQ(header_float(ours, 0), 1.0f);
    EXPECT_NEAR(header_float(ours, 24), header_float(theirs, 24), 5e-6 * header_float(theirs, 24));
}

// Read as written (1 um, see the data README): V(1000 nm) = 0, so both state 0 lm.
TEST(ZemaxSpeosConversion, SdfToSpeosMatchesTheReferenceConversion) {
    RAYSET_REQUIRE_SHARED_DATA();
    test::ScratchDir dir;
    const std::string ours = convert(dir, "test_08_sdf.sdf", RayFormat::speos);
    const std::string theirs = rayfile("test_08_sdf_reference.ray");
    expect_same_rays(ours, theirs);
    EXPECT_EQ(header_float(ours, 24), 0.0f);
    EXPECT_EQ(header_float(theirs, 24), 0.0f);
}

// Header codes (units, ray format, flux type) and the source and ray-set fluxes come out as the
// reference wrote them; SPEOS's luminous total has no place in a watts file.
TEST(ZemaxSpeosConversion, SpeosToSdfMatchesTheReferenceConversion) {
    RAYSET_REQUIRE_SHARED_DATA();
    test::ScratchDir dir;
    const std::string ours =
        convert(dir, "test_08_ray.ray", RayFormat::zemax_binary,
                {"stated luminous total (Zemax states one total: watts here)"});
    const std::string theirs = rayfile("test_08_ray_reference.sdf");
    expect_same_rays(ours, theirs);
    const std::string a = test::read_file(ours), b = test::read_file(theirs);
    ASSERT_EQ(a.size(), b.size());
    EXPECT_EQ(a.substr(0, 8), b.substr(0, 8));        // identifier, count
    EXPECT_EQ(a.substr(108, 8), b.substr(108, 8));    // source and ray-set flux
    EXPECT_EQ(a.substr(136, 4), b.substr(136, 4));    // units
    EXPECT_EQ(a.substr(192, 16), b.substr(192, 16));  // ray format, flux type, reserved
}

}  // namespace
}  // namespace rayset
