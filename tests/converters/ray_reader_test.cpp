// RayReader decodes and validates ahead of read() on a thread of its own: what the caller sees
// must be what a reader without that thread would give, errors included, in the same order.
#include <gtest/gtest.h>

#include "converters/codecs.h"
#include "converters/ray_stream.h"
#include "support/test_support.h"

#include <cmath>

namespace rayset {
namespace {

constexpr uint64_t kRecord = 28;        // x y z kx ky kz radiant (formats.md)
constexpr uint64_t kDataStart = 36288;  // no tables, labels or text

// Ray i: origin (i, 0, 0), direction +z, radiant flux (i % 7 + 1) / 8 W (exact in float).
float flux_of(size_t i) { return float(i % 7 + 1) / 8; }

std::string write_file(const test::ScratchDir& dir, size_t rays, size_t bad_ray = SIZE_MAX) {
    RayHeader h;
    h.has_radiant = true;
    const std::string path = dir.file("rays.tm25ray");
    auto encoder = create_tm25(path, h);
    RayChunk chunk;
    for (size_t i = 0; i < rays; ++i) {
        Ray r;
        r.origin = {float(i), 0, 0};
        r.direction = {0, 0, i == bad_ray ? std::nanf("") : 1.0f};
        r.radiant = flux_of(i);
        chunk.rays.push_back(r);
    }
    encoder->write(chunk);
    encoder->finish();
    return path;
}

RayReadOptions chunks_of(size_t rays) {
    RayReadOptions options;
    options.chunk_size = rays;
    return options;
}

TEST(RayReader, HandsOutEveryRayInOrderWithTheirTotals) {
    test::ScratchDir dir;
    const size_t n = 25001;  // not a multiple of the chunk size
    auto reader = open_rays(write_file(dir, n), chunks_of(1000));
    RayChunk chunk;
    size_t next = 0;
    double sum = 0;
    while (reader->read(chunk)) {
        ASSERT_EQ(chunk.first_index, next);
        for (const Ray& r : chunk.rays) {
            ASSERT_EQ(r.origin.x, float(next));
            ASSERT_EQ(r.radiant, flux_of(next));
            sum += flux_of(next);
            ++next;
        }
        EXPECT_EQ(reader->totals().rays, next);
    }
    EXPECT_EQ(next, n);
    // Sums of multiples of 1/8 below 2^50 are exact in double, in any order.
    EXPECT_EQ(reader->totals().radiant, sum);
    EXPECT_FALSE(reader->read(chunk));  // the end stays the end
}

TEST(RayReader, AnErrorComesAfterTheRaysBeforeIt) {
    test::ScratchDir dir;
    const size_t bad = 9000;
    const std::string path = write_file(dir, 20000, bad);
    auto reader = open_rays(path, chunks_of(1000));
    RayChunk chunk;
    uint64_t handed_out = 0;
    std::string message;
    try {
        while (reader->read(chunk)) handed_out += chunk.size();
    } catch (const Error& e) {
        message = e.what();
    }
    // The chunks before the bad ray's chunk arrive whole; the bad ray's chunk does not.
    EXPECT_EQ(handed_out, bad);
    EXPECT_EQ(reader->totals().rays, bad);
    EXPECT_EQ(message, path + ": byte " + std::to_string(kDataStart + bad * kRecord) + ": ray " + std::to_string(bad + 1) +
                           ": direction (0, 0, nan) is not a finite number");
    // Asking again gives the same error, not rays past it.
    EXPECT_THROW(reader->read(chunk), Error);
}

TEST(RayReader, CanBeDroppedBeforeTheEnd) {
    test::ScratchDir dir;
    const std::string path = write_file(dir, 50000);
    for (int stop_after : {0, 1, 3}) {
        auto reader = open_rays(path, chunks_of(500));
        RayChunk chunk;
        for (int k = 0; k < stop_after; ++k) ASSERT_TRUE(reader->read(chunk));
        reader.reset();  // joins the read-ahead thread, which may be waiting for room
    }
}

}  // namespace
}  // namespace rayset
