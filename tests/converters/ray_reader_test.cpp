// RayReader decodes and validates ahead of read() on threads of its own, and reads a file in
// parts on several threads for read_in_parts(): what the caller sees must be what a reader
// without those threads would give, errors included.
#include <gtest/gtest.h>

#include "converters/formats/codecs.h"
#include "converters/rays/ray_stream.h"
#include "support/test_support.h"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <set>
#include <vector>

namespace rayset {
namespace {

constexpr uint64_t kRecord = 28;        // x y z kx ky kz radiant (formats.md)
constexpr uint64_t kDataStart = 36288;  // no tables, labels or text

// Ray i: origin (i, 0, 0), direction +z, radiant flux (i % 7 + 1) / 8 W (exact in float).
float flux_of(size_t i) { return float(i % 7 + 1) / 8; }

// Rays 0..n-1 as described above.
RayChunk numbered_rays(size_t n) {
    RayChunk chunk;
    for (size_t i = 0; i < n; ++i) {
        Ray r;
        r.origin = {float(i), 0, 0};
        r.direction = {0, 0, 1};
        r.radiant = flux_of(i);
        chunk.rays.push_back(r);
    }
    return chunk;
}

std::string write_file(const test::ScratchDir& dir, size_t rays, std::set<size_t> bad_rays = {}) {
    RayHeader h;
    h.has_radiant = true;
    const std::string path = dir.file("rays.tm25ray");
    auto encoder = create_tm25(path, h);
    RayChunk chunk = numbered_rays(rays);
    for (size_t i : bad_rays) chunk.rays[i].direction.z = std::nanf("");
    encoder->write(chunk);
    encoder->finish();
    return path;
}

RayReadOptions chunks_of(size_t rays) {
    RayReadOptions options;
    options.chunk_size = rays;
    return options;
}

// Reads a file of write_file()'s n good rays to the end: every ray once, in order, in chunks of
// `chunk_size`, with the running totals.
void expect_every_ray_in_order(RayReader& reader, size_t n, size_t chunk_size) {
    RayChunk chunk;
    size_t next = 0;
    double sum = 0;
    while (reader.read(chunk)) {
        ASSERT_EQ(chunk.first_index, next);
        ASSERT_EQ(chunk.size(), std::min(chunk_size, n - next));
        for (const Ray& r : chunk.rays) {
            ASSERT_EQ(r.origin.x, float(next));
            ASSERT_EQ(r.direction.z, 1.0f);
            ASSERT_EQ(r.radiant, flux_of(next));
            ASSERT_TRUE(std::isnan(r.luminous) && std::isnan(r.wavelength) && r.spectrum == -1);
            sum += flux_of(next);
            ++next;
        }
        EXPECT_EQ(reader.totals().rays, next);
    }
    EXPECT_EQ(next, n);
    // Sums of multiples of 1/8 below 2^50 are exact in double, in any order.
    EXPECT_EQ(reader.totals().radiant, sum);
    EXPECT_FALSE(reader.read(chunk));  // the end stays the end
}

// Reads until an error: how many rays came before it, and its message.
struct ReadToError {
    uint64_t handed_out = 0;
    std::string message;
};
ReadToError read_to_error(RayReader& reader) {
    ReadToError result;
    RayChunk chunk;
    try {
        while (reader.read(chunk)) result.handed_out += chunk.size();
    } catch (const Error& e) {
        result.message = e.what();
    }
    return result;
}

std::string bad_direction_message(const std::string& path, size_t bad) {
    return path + ": byte " + std::to_string(kDataStart + bad * kRecord) + ": ray " +
           std::to_string(bad + 1) + ": direction (0, 0, nan) is not a finite number";
}

TEST(RayReader, HandsOutEveryRayInOrderWithTheirTotals) {
    test::ScratchDir dir;
    const size_t n = 25001;  // not a multiple of the chunk size
    auto reader = open_rays(write_file(dir, n), chunks_of(1000));
    expect_every_ray_in_order(*reader, n, 1000);
}

TEST(RayReader, AnErrorComesAfterTheRaysBeforeIt) {
    test::ScratchDir dir;
    const size_t bad = 9000;
    const std::string path = write_file(dir, 20000, {bad});
    auto reader = open_rays(path, chunks_of(1000));
    const ReadToError read = read_to_error(*reader);
    // The chunks before the bad ray's chunk arrive whole; the bad ray's chunk does not.
    EXPECT_EQ(read.handed_out, bad);
    EXPECT_EQ(reader->totals().rays, bad);
    EXPECT_EQ(read.message, bad_direction_message(path, bad));
    // Asking again gives the same error, not rays past it.
    RayChunk chunk;
    EXPECT_THROW(reader->read(chunk), Error);
}

// The validity rule is one for the whole-chunk test and the ray-by-ray report: a wavelength of
// 0 is refused (NaN means unknown), also inside a chunk whose other rays are all valid.
TEST(RayReader, AWavelengthOfZeroIsRefused) {
    test::ScratchDir dir;
    RayHeader h;
    h.has_radiant = true;
    h.spectral = SpectralKind::per_ray_wavelength;
    const std::string path = dir.file("zero.tm25ray");
    auto encoder = create_tm25(path, h);
    RayChunk chunk = numbered_rays(3000);
    for (size_t i = 0; i < 3000; ++i)
        chunk.rays[i].wavelength = i == 1500 ? 0.0f : i == 10 ? std::nanf("") : 450.0f;
    encoder->write(chunk);
    encoder->finish();
    auto reader = open_rays(path, chunks_of(1000));
    const ReadToError read = read_to_error(*reader);
    EXPECT_EQ(read.handed_out, 1000u);
    EXPECT_NE(read.message.find(": ray 1501: wavelength 0 nm is not a positive number"),
              std::string::npos)
        << read.message;
}

// Files of fixed-size records that span enough chunks are decoded ahead on several threads
// (as many as parts(), up to the cores), each taking every T-th chunk: what read() hands out
// must still be every ray once, in file order, with the same totals. (With one core there is
// one thread, and these tests check what the ones above do.)
TEST(RayReader, DecodingOnSeveralThreadsHandsOutEveryRayInOrder) {
    test::ScratchDir dir;
    const size_t n = 25001;  // 251 chunks of 100, the last of 1
    auto reader = open_rays(write_file(dir, n), chunks_of(100));
    ASSERT_GT(reader->parts(), 1u);
    expect_every_ray_in_order(*reader, n, 100);
}

// Bad rays in two neighbouring chunks, which two threads decode at once (the later one is
// often found first): the error is the first bad ray's, after every ray before it, each time.
TEST(RayReader, DecodingOnSeveralThreadsReportsTheFirstBadRay) {
    test::ScratchDir dir;
    const size_t first_bad = 9050, second_bad = 9120;  // chunks 90 and 91 of 100 rays
    const std::string path = write_file(dir, 20000, {first_bad, second_bad});
    for (int attempt = 0; attempt < 20; ++attempt) {
        auto reader = open_rays(path, chunks_of(100));
        ASSERT_GT(reader->parts(), 1u);
        const ReadToError read = read_to_error(*reader);
        EXPECT_EQ(read.handed_out, 9000u)
            << "attempt " << attempt;  // the chunks before the bad ray's
        EXPECT_EQ(read.message, bad_direction_message(path, first_bad)) << "attempt " << attempt;
        RayChunk chunk;
        EXPECT_THROW(reader->read(chunk), Error);
    }
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

// What read_in_parts() handed out: each part's chunks as (first index, size), in the order seen.
struct Visits {
    std::mutex mutex;
    std::vector<std::vector<std::pair<uint64_t, size_t>>> chunks;
    bool values_right = true;
};

void read_all_in_parts(RayReader& reader, Visits& visits) {
    visits.chunks.resize(reader.parts());
    reader.read_in_parts([&](size_t part, const RayColumns& chunk) {
        bool right = true;
        for (size_t i = 0; i < chunk.size(); ++i) {
            const uint64_t index = chunk.first_index + i;
            right &= chunk.ox[i] == float(index) && chunk.radiant[i] == flux_of(index) &&
                     chunk.dz[i] == 1.0f;
        }
        std::lock_guard<std::mutex> lock(visits.mutex);
        visits.chunks.at(part).emplace_back(chunk.first_index, chunk.size());
        visits.values_right &= right;
    });
}

TEST(RayReaderInParts, VisitsEveryRayOnceInConsecutivePartsWithTheTotalsOfRead) {
    test::ScratchDir dir;
    const size_t n = 25001;  // 8 parts of 3125 or 3126 rays, chunks of 100
    const std::string path = write_file(dir, n);
    auto reader = open_rays(path, chunks_of(100));
    ASSERT_EQ(reader->parts(), RayReader::kMaxParts);
    Visits visits;
    read_all_in_parts(*reader, visits);
    EXPECT_TRUE(visits.values_right);
    // Part p holds rays [n p / 8, n (p + 1) / 8), its chunks one after another in file order.
    uint64_t next = 0;
    double sum = 0;
    for (size_t p = 0; p < visits.chunks.size(); ++p) {
        EXPECT_EQ(next, n * p / RayReader::kMaxParts) << "part " << p;
        for (const auto& [first, size] : visits.chunks[p]) {
            ASSERT_EQ(first, next) << "part " << p;
            for (size_t i = 0; i < size; ++i) sum += flux_of(next + i);
            next += size;
        }
    }
    EXPECT_EQ(next, n);
    EXPECT_EQ(reader->totals().rays, n);
    EXPECT_EQ(reader->totals().radiant, sum);  // multiples of 1/8: exact in any order
    EXPECT_DOUBLE_EQ(reader->progress(), 1.0);
    // read() over the same file gives the same totals.
    auto sequential = open_rays(path, chunks_of(100));
    RayChunk chunk;
    while (sequential->read(chunk)) {
    }
    EXPECT_EQ(sequential->totals().radiant, reader->totals().radiant);
    EXPECT_EQ(sequential->totals().rays, reader->totals().rays);
}

TEST(RayReaderInParts, ReportsTheFirstBadRayOfTheFileWhicheverPartFailsFirst) {
    test::ScratchDir dir;
    // Bad rays at the end of part 0 and the start of part 1 (of 8, 10000 rays each), which
    // two threads start on at once: part 1 mostly fails first, and part 0 must still be read
    // up to its own bad ray, the one to report.
    const std::string path = write_file(dir, 80000, {9950, 10000});
    const std::string expected = path + ": byte " + std::to_string(kDataStart + 9950 * kRecord) +
                                 ": ray 9951: direction (0, 0, nan) is not a finite number";
    for (int attempt = 0; attempt < 20; ++attempt) {  // thread timing differs from run to run
        auto reader = open_rays(path, chunks_of(100));
        ASSERT_EQ(reader->parts(), RayReader::kMaxParts);
        try {
            Visits visits;
            read_all_in_parts(*reader, visits);
            ADD_FAILURE() << "no error";
        } catch (const Error& e) {
            EXPECT_EQ(std::string(e.what()), expected);
        }
    }
}

TEST(RayReaderInParts, SmallFilesAndTextFormatsAreOnePart) {
    test::ScratchDir dir;
    // Fewer than 16 chunks per part would give a second part no work worth a thread.
    auto small = open_rays(write_file(dir, 1599), chunks_of(100));
    EXPECT_EQ(small->parts(), 1u);
    // Text files cannot seek to a ray: one part, read front to back.
    RayHeader h;
    h.has_radiant = true;
    const std::string csv = dir.file("rays.csv");
    auto encoder = create_rays(csv, RayFormat::csv, h);
    encoder->write(numbered_rays(5000));
    encoder->finish();
    auto reader = open_rays(csv, chunks_of(100));
    EXPECT_EQ(reader->parts(), 1u);
    Visits visits;
    read_all_in_parts(*reader, visits);
    EXPECT_TRUE(visits.values_right);
    ASSERT_EQ(visits.chunks.size(), 1u);
    EXPECT_EQ(visits.chunks[0].size(), 50u);
    EXPECT_EQ(reader->totals().rays, 5000u);
}

}  // namespace
}  // namespace rayset
