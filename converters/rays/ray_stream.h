// Streaming access to ray files of every supported format: open_rays() detects the format
// from the content, validates every ray and scales relative fluxes; create_rays() writes any
// format. Memory stays constant in the number of rays.
#pragma once

#include "converters/rays/ray.h"
#include "core/error.h"

#include <atomic>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rayset {

// What a codec hands out, before validation and scaling. Implemented once per format.
class RayDecoder {
public:
    virtual ~RayDecoder() = default;
    const RayHeader& header() const { return header_; }
    // Puts the next up to max_rays rays (and their extras) into `columns` after clearing it and
    // setting columns.first_index. Returns false when no ray is left.
    virtual bool decode(RayColumns& columns, size_t max_rays) = 0;
    // The same rays as records, for tests and tools that look at one decoder's rays as they are.
    bool read(RayChunk& chunk, size_t max_rays);
    // Where ray `index` is in the file, for error messages ("byte 36928", "line 14").
    virtual Location locate(uint64_t index) const = 0;
    // Per-ray fluxes that are relative by the format's definition (LightTools, Zemax, SPEOS):
    // they are scaled to the stated total unless the user says otherwise.
    virtual bool flux_is_relative() const { return false; }
    // Formats of fixed-size records can start at any ray (RayReader::read_in_parts opens a
    // decoder per part and seeks); seek() is called before the first decode(), if at all.
    virtual bool can_seek() const { return false; }
    virtual void seek(uint64_t /*index*/) {}

protected:
    RayHeader header_;

private:
    RayColumns scratch_;  // for read()
};

// Writes one format. Call write() for every chunk, then finish(), which patches counts and
// totals into the header and renames the file into place. Destroying an unfinished writer
// leaves no file behind.
class RayEncoder {
public:
    virtual ~RayEncoder() = default;
    virtual void write(const RayChunk& chunk) = 0;
    virtual void finish() = 0;
    // Fields of the header the target format cannot hold (reported to the user).
    const std::vector<std::string>& dropped() const { return dropped_; }

protected:
    std::vector<std::string> dropped_;
};

// Which total wins when the stated total and the sum of the rays disagree beyond rounding.
enum class FluxPolicy {
    format_default,  // relative formats: the stated total; TM-25 and CSV: the rays
    stated,          // scale the rays to the total the header states
    rays,            // keep the rays as they are
};

struct RayReadOptions {
    FluxPolicy flux_policy = FluxPolicy::format_default;
    // Directions whose length differs from 1 by more than this are an error.
    float direction_tolerance = 1e-3f;
    // Accept non-unit directions and normalise them instead of failing.
    bool normalise_directions = false;
    size_t chunk_size = 1 << 12;
    std::optional<RayFormat> format;  // skip detection
};

// Summed fluxes as the reader hands them out (after scaling).
struct RayTotals {
    double radiant = 0, luminous = 0;
    uint64_t rays = 0;
    uint64_t zero_flux_rays = 0;

    RayTotals& operator+=(const RayTotals& more) {
        radiant += more.radiant, luminous += more.luminous;
        rays += more.rays, zero_flux_rays += more.zero_flux_rays;
        return *this;
    }
};

// The validating, scaling reader over a decoder. read() hands out the rays in order; decoding
// and validation run a few chunks ahead of it on threads of the reader's own - one, or for
// large files of fixed-size records as many as parts() and the cores allow (memory: two chunks
// of RayReadOptions::chunk_size rays per thread, and two more). read_in_parts() is for
// consumers to whom the order does not matter (summaries, histograms): it reads the file in
// parts on several threads at once. A reader is read once, one way; call it from one thread.
class RayReader {
public:
    RayReader(std::unique_ptr<RayDecoder> decoder, std::string path, RayReadOptions options);
    ~RayReader();

    const std::string& path() const { return path_; }
    // The header with stated totals replaced by what the rays will sum to when the rays are
    // scaled (stated_* keeps the file's own figures in file_header()).
    const RayHeader& header() const { return header_; }
    const RayHeader& file_header() const { return decoder_->header(); }
    double radiant_scale() const { return radiant_scale_; }
    double luminous_scale() const { return luminous_scale_; }

    // Next chunk of validated rays; false at the end. Throws Error naming the ray's location.
    bool read(RayChunk& chunk);

    // The number of parts read_in_parts() reads: up to kMaxParts consecutive ranges of rays, a
    // number that depends on the file alone (not on the machine), so that whatever a consumer
    // sums per part and merges in part order comes out the same everywhere. One part for small
    // files and for formats that cannot seek (the text ones).
    static constexpr size_t kMaxParts = 8;
    size_t parts() const;
    // Reads every ray, calling visit(part, chunk) with each validated chunk: a part's chunks in
    // order and on one thread, the parts on up to as many threads as the machine has cores.
    // `progress` (if set) is called on the calling thread. Totals, warnings and the error of
    // the first bad ray in the file come out as read() would give them.
    void read_in_parts(const std::function<void(size_t part, const RayColumns& chunk)>& visit,
                       const std::function<void(double)>& progress = {});

    const RayTotals& totals() const { return totals_; }  // of the rays read so far
    // Warnings found so far (stated total disagrees, zero-flux rays, ...), one line each.
    const std::vector<std::string>& warnings() const { return warnings_; }
    // Fraction of the file read, for progress bars.
    double progress() const;

private:
    friend std::unique_ptr<RayReader> open_rays(const std::string& path,
                                                const RayReadOptions& options);
    class ReadAhead;
    // Checks and scales a chunk (on the read-ahead thread: it changes nothing but the chunk).
    RayTotals validate(RayColumns& chunk) const;
    void check_ray(RayColumns& chunk, size_t index) const;
    void finish();  // the checks that need every ray, at the end

    std::unique_ptr<RayDecoder> decoder_;
    std::string path_;
    RayReadOptions options_;
    RayHeader header_;
    double radiant_scale_ = 1, luminous_scale_ = 1;
    RayTotals totals_;
    std::vector<std::string> warnings_;
    std::function<std::unique_ptr<RayDecoder>()>
        reopen_;                              // how open_rays() made the decoder (one per part)
    std::atomic<uint64_t> rays_in_parts_{0};  // read so far by read_in_parts(), for progress()
    std::unique_ptr<ReadAhead> ahead_;        // started by the first read()
};

std::unique_ptr<RayReader> open_rays(const std::string& path, const RayReadOptions& options = {});

// Creates a writer of `format` at `path` for rays described by `header` (its unit, flux
// columns, spectral kind and extras say what each ray carries).
std::unique_ptr<RayEncoder> create_rays(const std::string& path, RayFormat format,
                                        const RayHeader& header);

// Content-based detection (the .ray extension is ambiguous). Throws Error when no format fits.
RayFormat detect_ray_format(const std::string& path);
// Format from a name a user types or a file extension: "tm25", ".TM25RAY", "lighttools", ...
std::optional<RayFormat> ray_format_from_name(const std::string& name);

// Whether a stated total and the sum of the rays agree "to rounding": within 1e-4 relative,
// which covers f32 totals and single-precision summation by other tools of up to ~10^7 rays.
bool totals_agree(double stated, double sum);
// The total an encoder of a relative format (whose total sets the rays' scale) writes: the
// stated one when the rays agree with it (so round trips are bit-exact), else the sum of the rays
// written, so the output means what was read. Absolute formats keep the stated total as it is.
double total_to_write(double stated, double sum);

// Streams every ray of `in` into `out`; `progress` (if set) is called with the fraction done.
void copy_rays(RayReader& in, RayEncoder& out, const std::function<void(double)>& progress = {});

}  // namespace rayset
