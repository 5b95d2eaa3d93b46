// Fuzzes the CSV (rayset) reader: each input is a file that open_rays() reads in that format
// (RayReadOptions::format), every ray of it, with the validation and flux scaling the tools get.
#include "fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string path = rayset::fuzz::write_input(data, size, "input.csv");
    rayset::fuzz::read_every_ray(path, rayset::RayFormat::csv);
    return 0;
}
