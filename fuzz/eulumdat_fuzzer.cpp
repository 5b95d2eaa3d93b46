// Fuzzes the EULUMDAT reader: each input is a file that read_eulumdat() reads, followed by what
// the tools do with a file once read: its Photometry, the flux and peak `rayconv info` prints,
// intensities between the grid angles (`rayconv emit`) and the IES form `rayconv convert`
// writes.
#include "converters/photometry/eulumdat.h"
#include "converters/photometry/ies.h"
#include "core/error.h"
#include "fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string path = rayset::fuzz::write_input(data, size, "input.ldt");
    try {
        const rayset::Photometry photometry =
            rayset::eulumdat_to_photometry(rayset::read_eulumdat(path));
        photometry.total_flux();
        photometry.max_candela();
        // Directions off the grid and outside the stored range, so that the symmetries are
        // unfolded and the interpolation runs.
        for (double horizontal = -135; horizontal <= 405; horizontal += 67.5)
            for (double vertical = -30; vertical <= 200; vertical += 57.5)
                photometry.intensity(horizontal, vertical);
        rayset::ies_from_photometry(photometry, path + ".ies");
    } catch (const rayset::Error& error) {
        // The reader or the conversion found the file bad and said where: what they should do.
        rayset::fuzz::expect_file_named(error, path);
    }
    return 0;
}
