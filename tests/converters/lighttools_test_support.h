// Helpers shared by the LightTools codec tests (lighttools_test.cpp, lighttools_text_test.cpp):
// rays spanning many exponents, hand-assembled binary files, bit-exact comparison, error checks.
#pragma once

#include "converters/formats/codecs.h"
#include "converters/rays/io.h"
#include "support/test_support.h"

#include <gtest/gtest.h>
#include <cmath>
#include <cstring>
#include <random>

namespace rayset::lighttools_test {

inline uint32_t bits(float f) {
    uint32_t u;
    std::memcpy(&u, &f, 4);
    return u;
}

inline std::vector<Ray> read_all(RayDecoder& decoder, size_t chunk_size = 7) {
    std::vector<Ray> rays;
    RayChunk chunk;
    while (decoder.read(chunk, chunk_size)) {
        EXPECT_EQ(chunk.first_index, rays.size());
        rays.insert(rays.end(), chunk.rays.begin(), chunk.rays.end());
    }
    return rays;
}

// Rays whose coordinates span many binary exponents, so that any lossy text or byte handling
// shows up as a changed bit.
inline std::vector<Ray> make_rays(size_t n, bool wavelength, bool photometric) {
    std::mt19937 rng(20240611);
    std::uniform_real_distribution<float> unit(-1, 1);
    std::uniform_int_distribution<int> exponent(-30, 30);
    std::vector<Ray> rays(n);
    for (Ray& r : rays) {
        r.origin = {std::ldexp(unit(rng), exponent(rng)), std::ldexp(unit(rng), exponent(rng)),
                    unit(rng)};
        float x = unit(rng), y = unit(rng), z = unit(rng);
        float len = std::sqrt(x * x + y * y + z * z);
        r.direction = {x / len, y / len, z / len};
        float flux = std::ldexp(std::abs(unit(rng)), exponent(rng) / 3);
        (photometric ? r.luminous : r.radiant) = flux;
        if (wavelength) r.wavelength = 380 + 400 * std::abs(unit(rng));
    }
    return rays;
}

inline RayHeader make_header(bool wavelength, bool photometric, LengthUnit unit) {
    RayHeader h;
    h.unit = unit;
    h.has_radiant = !photometric;
    h.has_luminous = photometric;
    h.spectral = wavelength ? SpectralKind::per_ray_wavelength : SpectralKind::none;
    h.data_origin = {1.5f, -2.25f, 1e-3f};
    h.description = "rayset test rays\nsecond comment line";
    h.text[0] = "testRays";
    return h;
}

inline void write_rays(RayEncoder& encoder, const std::vector<Ray>& rays, size_t chunk_size = 5) {
    for (size_t i = 0; i < rays.size(); i += chunk_size) {
        RayChunk chunk;
        chunk.first_index = i;
        chunk.rays.assign(rays.begin() + i, rays.begin() + std::min(rays.size(), i + chunk_size));
        encoder.write(chunk);
    }
    encoder.finish();
}

inline void expect_same_rays(const std::vector<Ray>& a, const std::vector<Ray>& b) {
    ASSERT_EQ(a.size(), b.size());
    for (size_t i = 0; i < a.size(); ++i) {
        const float fa[9] = {a[i].origin.x,    a[i].origin.y,    a[i].origin.z,
                             a[i].direction.x, a[i].direction.y, a[i].direction.z,
                             a[i].radiant,     a[i].luminous,    a[i].wavelength};
        const float fb[9] = {b[i].origin.x,    b[i].origin.y,    b[i].origin.z,
                             b[i].direction.x, b[i].direction.y, b[i].direction.z,
                             b[i].radiant,     b[i].luminous,    b[i].wavelength};
        for (int j = 0; j < 9; ++j) {
            if (std::isnan(fa[j]) && std::isnan(fb[j])) continue;  // "not carried" on both sides
            ASSERT_EQ(bits(fa[j]), bits(fb[j]))
                << "ray " << i << " value " << j << ": " << fa[j] << " vs " << fb[j];
        }
    }
}

// A binary file assembled byte by byte, independently of the writer.
inline std::string binary_file(uint32_t data_type, uint32_t far_field, uint32_t colour,
                               uint32_t unit, float total, const std::vector<float>& values,
                               bool trailer = true) {
    std::string bytes = "LTRF";
    auto put = [&](const void* p, size_t n) { bytes.append(static_cast<const char*>(p), n); };
    const uint32_t header[6] = {2, 0, data_type, far_field, colour, unit};
    put(header, sizeof header);
    const float origin_total[4] = {0.5f, 0, -1, total};
    put(origin_total, sizeof origin_total);
    put(values.data(), values.size() * 4);
    if (trailer) bytes += "LTRFEND";
    return bytes;
}

inline const std::vector<float> kTwoRays7 = {1,  2, 3, 0,    0,    1, 0.25f,
                                             -4, 5, 6, 0.6f, 0.8f, 0, 0.75f};

// Opens and reads the whole file, expecting an Error that starts with the path and holds `parts`.
inline void expect_open_error(std::unique_ptr<RayDecoder> (*open)(const std::string&),
                              const std::string& path, const std::vector<std::string>& parts) {
    try {
        auto d = open(path);
        RayChunk chunk;
        while (d->read(chunk, 1000)) {
        }
        FAIL() << "no error for " << path;
    } catch (const Error& e) {
        const std::string message = e.what();
        EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
        for (const std::string& part : parts)
            EXPECT_NE(message.find(part), std::string::npos)
                << "'" << part << "' not in: " << message;
    }
}

}  // namespace rayset::lighttools_test
