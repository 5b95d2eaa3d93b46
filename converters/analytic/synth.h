// Synthetic ray files from the analytic sources: build a source from its name and key=value
// parameters (as `rayconv synth` takes them), describe its rays in a RayHeader, and stream
// equal-flux rays into any ray-file writer with constant memory.
#pragma once

#include "converters/analytic/analytic_sources.h"
#include "converters/rays/ray_stream.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace rayset {

// Parameters in the order given: {"radius", "2"}, ...
using SourceParameters = std::vector<std::pair<std::string, std::string>>;

// Splits words of the form key=value; throws Error for a word without '=', an empty key or a
// key given twice.
SourceParameters parse_source_parameters(const std::vector<std::string>& words);

// The source `name` (disk, rectangle, sphere, lobe, cluster) with `parameters`; unset ones take
// the defaults source_help() lists. Throws Error naming the unknown source or key (and the
// known ones), a value that is not a number, or a value out of range.
std::unique_ptr<analytic::Source> make_source(const std::string& name,
                                              const SourceParameters& parameters);

// Every source with its keys, units and defaults, one line per key, for --help.
std::string source_help();

// A spectral table from a text file of two columns (wavelength nm, relative power), separated
// by spaces, tabs or a comma; '#' starts a comment line. Wavelengths must ascend.
analytic::Spectrum read_spectrum_file(const std::string& path);

struct SynthOptions {
    // Also give every ray its luminous flux (lm) from its radiant flux and spectrum, V(lambda).
    bool luminous = true;
    size_t chunk_size = 1 << 16;
    std::function<void(double)> progress;  // fraction done
};

// The header of the rays synthesize() writes: mm, radiant flux (and luminous), the source's
// spectral kind, stated totals (no luminous total with a wavelength per ray: it depends on the
// draw), text fields naming the source, its parameters, count and seed.
RayHeader synth_header(const analytic::Source& source, uint64_t ray_count, uint64_t seed,
                       const SynthOptions& options = {});

// Writes ray_count rays of equal radiant flux total/ray_count (rounded to float once) drawn
// with Pcg32(seed) into `out`, then calls out.finish(). The same seed gives the same rays.
// `out` must have been created with synth_header() of the same arguments.
void synthesize(const analytic::Source& source, uint64_t ray_count, uint64_t seed, RayEncoder& out,
                const SynthOptions& options = {});

}  // namespace rayset
