// Fuzzes the reader of light-model files (.vdb, lightmodel/model_file.h): each input is a file
// that read_model() reads - our guarded archive reading (lightmodel/vdb_file.h), OpenVDB's
// file layer beneath it (Debian's library, not instrumented: its branches do not guide the
// fuzzer, but a crash in it is still caught) and our reading of the grids and metadata into a
// LightModel (instrumented). Every length OpenVDB would allocate at is checked before it reads
// it, so that an allocation larger than libFuzzer's -malloc_limit_mb (its -rss_limit_mb, 2 GB)
// from an input of at most 128 kB is a finding like any other.
#include "core/error.h"
#include "fuzz/fuzz_support.h"
#include "lightmodel/model_file.h"

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
