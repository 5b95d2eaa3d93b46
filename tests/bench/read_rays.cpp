// read_rays [--sequential] FILE: reads every ray of a ray file through the library's reader and
// does nothing else with them. By default as `rayconv info` does (detect the format, decode,
// validate, sum the fluxes; in parts on every core where the format allows): the reading
// without info's summary (bounding box, wavelengths, direction coverage). With --sequential as
// `rayconv convert` and the other commands do: chunks of ray records in file order, decoded and
// validated on a read-ahead thread. io_throughput.sh times them against `cat`.
#include "converters/rays/ray_stream.h"
#include "core/error.h"

#include <cstdio>
#include <cstring>

int main(int argc, char** argv) {
    const bool sequential = argc == 3 && std::strcmp(argv[1], "--sequential") == 0;
    if (argc != 2 && !sequential) {
        std::fprintf(stderr, "usage: read_rays [--sequential] FILE\n");
        return 2;
    }
    try {
        auto reader = rayset::open_rays(argv[argc - 1]);
        if (sequential) {
            rayset::RayChunk chunk;
            while (reader->read(chunk)) {
            }
        } else {
            reader->read_in_parts([](size_t, const rayset::RayColumns&) {});
        }
        const rayset::RayTotals& totals = reader->totals();
        std::printf("%llu rays, %.9g W, %.9g lm\n", static_cast<unsigned long long>(totals.rays),
                    totals.radiant, totals.luminous);
    } catch (const rayset::Error& e) {
        std::fprintf(stderr, "read_rays: %s\n", e.what());
        return 1;
    }
}
