// Fuzzes the reader of light-model files (.vdb, lightmodel/model_file.h): each input is a file
// that read_model() reads - OpenVDB's file layer (Debian's library, not instrumented: its
// branches do not guide the fuzzer, but a crash or a huge allocation in it is still caught) and
// our reading of the grids and metadata into a LightModel (instrumented).
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
