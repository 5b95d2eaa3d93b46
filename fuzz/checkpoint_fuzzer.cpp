// Fuzzes the reader of render checkpoints (`raytrace --resume`, tracer/film/checkpoint.h): each
// input is a checkpoint that read_checkpoint() reads for the render of checkpoint_render.h. A
// checkpoint ends with a checksum of every byte before it; the harness writes the right one over
// the input's last 8 bytes, so that the fuzzer's changes reach the fields behind the checksum
// rather than all stopping at it.
#include "core/error.h"
#include "fuzz/checkpoint_render.h"
#include "fuzz/fuzz_support.h"

#include <cstring>
#include <string>

namespace {

// FNV-1a, as checkpoint.cpp computes it.
uint64_t checksum(const uint8_t* data, size_t size) {
    uint64_t value = 0xCBF29CE484222325ULL;
    for (size_t i = 0; i < size; ++i) value = (value ^ data[i]) * 0x100000001B3ULL;
    return value;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::string bytes(reinterpret_cast<const char*>(data), size);
    if (bytes.size() >= 8) {
        const uint64_t sum = checksum(data, size - 8);
        std::memcpy(bytes.data() + bytes.size() - 8, &sum, 8);
    }
    const std::string path = rayset::fuzz::write_input(
        reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size(), "input.checkpoint");
    try {
        rayset::tracer::read_checkpoint(path, rayset::fuzz::checkpoint_identity(),
                                        rayset::fuzz::blank_checkpoint_render());
    } catch (const rayset::Error& error) {
        rayset::fuzz::expect_file_named(error, path);
    }
    return 0;
}
