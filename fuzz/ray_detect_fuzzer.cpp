// Fuzzes format detection: each input is a file whose format detect_ray_format() decides from
// its content (as rayconv does without --from), which is then read as that format, every ray
// of it. Inputs that detection refuses end there.
#include "converters/rays/ray_stream.h"
#include "core/error.h"
#include "fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    // ".ray": the extension several formats share, so that nothing but the content decides.
    const std::string path = rayset::fuzz::write_input(data, size, "input.ray");
    rayset::RayFormat format;
    try {
        format = rayset::detect_ray_format(path);
    } catch (const rayset::Error& error) {
        rayset::fuzz::expect_file_named(error, path);
        return 0;  // no format fits, and detection said so
    }
    rayset::fuzz::read_every_ray(path, format);
    return 0;
}
