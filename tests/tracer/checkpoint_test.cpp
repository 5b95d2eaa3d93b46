// Checkpoint files at the library level: a corrupt field behind a valid checksum is refused with
// the file, the byte and what is wrong. Offsets are computed from the layout checkpoint.h
// documents, not from the reader.
#include "tracer/film/checkpoint.h"

#include <gtest/gtest.h>

#include <cstring>

#include "core/error.h"
#include "support/test_support.h"

namespace rayset::tracer {
namespace {

CheckpointIdentity identity() {
    CheckpointIdentity id;
    id.scene = "scene.pov";
    id.width = 3, id.height = 2;
    id.integrator = "path";
    return id;
}

RenderResult blank() {
    RenderResult state;
    state.film = Film(3, 2);
    return state;
}

// FNV-1a over every byte before the last 8, as checkpoint.h describes the checksum.
void rewrite_checksum(std::string& bytes) {
    uint64_t value = 0xCBF29CE484222325ULL;
    for (size_t i = 0; i + 8 < bytes.size(); ++i)
        value = (value ^ static_cast<unsigned char>(bytes[i])) * 0x100000001B3ULL;
    std::memcpy(bytes.data() + bytes.size() - 8, &value, 8);
}

std::string error_reading(const std::string& path) {
    try {
        read_checkpoint(path, identity(), blank());
    } catch (const Error& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(Checkpoint, ImageSampleCountBeyondAnIntIsRefusedNamingItsByte) {
    test::ScratchDir dir;
    const std::string path = dir.file("scene.checkpoint");
    RenderResult state = blank();
    state.film.add(1, 1, {1, 2, 3});
    state.film.finish_pass();
    state.passes = 1;
    write_checkpoint(path, identity(), state);
    ASSERT_EQ(error_reading(path), "(no error)");

    // "RAYSETCK", version; identity: scene string (4 + 9), hash, width, height, seed, integrator
    // string (4 + 4), render_image, photons per pass, photon radius, naive sources; state:
    // passes, seconds, rays, photons, photon radius, photon bytes, visible point bytes; then the
    // image's nx and ny before its sample count.
    const size_t identity_bytes = (4 + 9) + 8 + 4 + 4 + 8 + (4 + 4) + 1 + 4 + 8 + 1;
    const size_t state_bytes = 4 + 8 + 8 + 8 + 8 + 8 + 8;
    const size_t samples_at = 8 + 4 + identity_bytes + state_bytes + 4 + 4;
    std::string bytes = test::read_file(path);
    uint32_t samples = 0;
    std::memcpy(&samples, bytes.data() + samples_at, 4);
    ASSERT_EQ(samples, 1u);  // the offset is the sample count's
    samples = 0x80000000u;
    std::memcpy(bytes.data() + samples_at, &samples, 4);
    rewrite_checksum(bytes);
    test::write_file(path, bytes);

    EXPECT_EQ(error_reading(path),
              path + ": byte " + std::to_string(samples_at) +
                  ": image counts 2147483648 samples, more than a render takes (at most "
                  "2147483647): the checkpoint is corrupt");
}

}  // namespace
}  // namespace rayset::tracer
