// Fuzzes the reader of light-model files (.vdb, lightmodel/model_file.h): each input is a file
// that read_model() reads - our guarded archive reading (lightmodel/vdb_file.h), OpenVDB's
// file layer beneath it (Debian's library, not instrumented: its branches do not guide the
// fuzzer, but a crash in it is still caught) and our reading of the grids and metadata into a
// LightModel (instrumented).
#include "core/error.h"
#include "fuzz/fuzz_support.h"
#include "lightmodel/model_file.h"

#include <cstdlib>
#include <new>

// OpenVDB 10 leaks the nodes it was reading when a corrupt file makes a node's readTopology()
// throw (the child is made with new and not yet owned by its parent): its bug, not ours.
extern "C" const char* __lsan_default_suppressions() { return "leak:readTopology\n"; }

// OpenVDB allocates what a file's length fields say before it finds the file too short: a
// corrupt grid descriptor asks for a 1.6 GB name, a metadata value for gigabytes (a real run gets
// what the machine has, fills it and frees it when the read then fails, or throws
// std::bad_alloc). Here an allocation above 256 MB throws std::bad_alloc, which read_model turns
// into its error when OpenVDB throws it; so such files do not stop the fuzzer at libFuzzer's
// -rss_limit_mb, while a bad_alloc from our own code escapes read_model and is still a finding.
// Every form but the aligned ones (which stay AddressSanitizer's) is replaced, so that what one
// allocates its partner frees; malloc is AddressSanitizer's, so its checks stay.
namespace {

void* allocate(std::size_t size) noexcept {
    constexpr std::size_t kLargest = std::size_t(256) << 20;
    return size <= kLargest ? std::malloc(size ? size : 1) : nullptr;
}

void* allocate_or_throw(std::size_t size) {
    if (void* memory = allocate(size)) return memory;
    throw std::bad_alloc();
}

}  // namespace

void* operator new(std::size_t size) { return allocate_or_throw(size); }
void* operator new[](std::size_t size) { return allocate_or_throw(size); }
void* operator new(std::size_t size, const std::nothrow_t&) noexcept { return allocate(size); }
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept { return allocate(size); }
void operator delete(void* memory) noexcept { std::free(memory); }
void operator delete[](void* memory) noexcept { std::free(memory); }
void operator delete(void* memory, std::size_t) noexcept { std::free(memory); }
void operator delete[](void* memory, std::size_t) noexcept { std::free(memory); }
void operator delete(void* memory, const std::nothrow_t&) noexcept { std::free(memory); }
void operator delete[](void* memory, const std::nothrow_t&) noexcept { std::free(memory); }

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string path = rayset::fuzz::write_input(data, size, "input.vdb");
    try {
        rayset::lightmodel::read_model(path);
    } catch (const rayset::Error& error) {
        // The reader found the file bad and said so: what it should do.
        rayset::fuzz::expect_file_named(error, path);
    }
    return 0;
}
