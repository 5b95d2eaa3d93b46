// read_rays FILE: reads every ray of a ray file through the library's reader as `rayconv info`
// does (detect the format, decode, validate, sum the fluxes; in parts on every core where the
// format allows) and does nothing else with them: the reading without info's summary (bounding
// box, wavelengths, direction coverage). io_throughput.sh times both against `cat`.
#include "converters/error.h"
#include "converters/ray_stream.h"

#include <cstdio>

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: read_rays FILE\n");
        return 2;
    }
    try {
        auto reader = rayset::open_rays(argv[1]);
        reader->read_in_parts([](size_t, const rayset::RayColumns&) {});
        const rayset::RayTotals& totals = reader->totals();
        std::printf("%llu rays, %.9g W, %.9g lm\n", static_cast<unsigned long long>(totals.rays), totals.radiant, totals.luminous);
    } catch (const rayset::Error& e) {
        std::fprintf(stderr, "read_rays: %s\n", e.what());
        return 1;
    }
}
