// RayReader: validation, flux scaling and totals over a decoder, with decoding and validating
// done ahead on a second thread (read) or in parts on several (read_in_parts); open_rays()
// and detection are in ray_stream.cpp.
#include "converters/rays/ray_stream.h"
#include "converters/rays/simd.h"

#include <fmt/format.h>
#include <algorithm>
#include <atomic>
#include <cmath>
#include <condition_variable>
#include <exception>
#include <limits>
#include <mutex>
#include <numeric>
#include <stdexcept>
#include <thread>
#include <vector>

namespace rayset {

// ---------------------------------------------------------------------------------------------
// Decoding and validating run ahead of read(), on threads of their own, so that they overlap
// with whatever the caller does with the rays (encoding, building). Chunk k (of
// options.chunk_size rays) goes to slot k % slot count: a decoding thread fills it once the
// caller has taken chunk k - slot count, and read() turns it into the caller's ray records - on
// the caller's thread, which would otherwise wait while the others decode - and frees it.
// Formats of fixed-size records that the reader can open again (as for read_in_parts) are
// decoded on as many threads as it has parts and the machine has cores, thread t taking
// chunks t, t + T, ... with a decoder of its own that seeks to each; the others on one thread.
// Memory stays at the slots' chunks of columns and the caller's records. The chunks, their
// totals and an error reach the caller in file order - an error after the chunks before it -
// as they would without the threads.
class RayReader::ReadAhead {
public:
    explicit ReadAhead(const RayReader& reader) : reader_(reader) {
        const size_t threads =
            std::min<size_t>(reader.parts(), std::max(1u, std::thread::hardware_concurrency()));
        slots_.resize(2 * threads + 2);
        free_ = std::vector<std::condition_variable>(threads);
        for (size_t t = 0; t < threads; ++t)
            threads_.emplace_back([this, t, threads] { run(t, threads); });
    }

    ~ReadAhead() {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            stopping_ = true;
        }
        for (auto& free : free_) free.notify_all();
        for (std::thread& t : threads_) t.join();
    }

    // The next chunk into `records` and its totals; false at the end. Rethrows a reading error.
    bool take(RayChunk& records, RayTotals& totals) {
        Slot* slot;
        {
            std::unique_lock<std::mutex> lock(mutex_);
            slot = &slots_[taken_ % slots_.size()];
            filled_.wait(lock, [slot] { return slot->filled; });
        }
        if (slot->error) std::rethrow_exception(slot->error);
        if (slot->end) return false;  // stays filled: later calls end again
        slot->columns.to_rays(records);
        totals = slot->totals;
        uint64_t freed_for;  // the chunk that may now use the slot
        {
            std::lock_guard<std::mutex> lock(mutex_);
            slot->filled = false;
            freed_for = taken_++ + slots_.size();
        }
        free_[freed_for % free_.size()].notify_one();  // the thread that decodes it
        return true;
    }

private:
    struct Slot {
        RayColumns columns;
        RayTotals totals;
        bool filled = false, end = false;
        std::exception_ptr error;
    };

    // Chunks first, first + step, ... until the end or an error.
    void run(size_t first, size_t step) {
        std::unique_ptr<RayDecoder> own;
        RayDecoder* decoder = first == 0 ? reader_.decoder_.get() : nullptr;
        const uint64_t chunk_size = reader_.options_.chunk_size, count = reader_.header_.ray_count;
        for (uint64_t k = first;; k += step) {
            {
                std::unique_lock<std::mutex> lock(mutex_);
                free_[first].wait(lock, [&] { return stopping_ || k < taken_ + slots_.size(); });
                if (stopping_) return;
            }
            // The slot is this thread's until it is marked filled.
            Slot& slot = slots_[k % slots_.size()];
            try {
                if (step == 1) {
                    slot.end = !decoder->decode(slot.columns, chunk_size);
                } else if (k * chunk_size >= count) {
                    slot.end = true;
                } else {
                    if (!decoder) own = reader_.reopen_(), decoder = own.get();
                    decoder->seek(k * chunk_size);
                    slot.end = !decoder->decode(slot.columns, chunk_size);
                }
                if (!slot.end) slot.totals = reader_.validate(slot.columns);
            } catch (...) {
                slot.error = std::current_exception();
            }
            const bool last = slot.end || slot.error;
            {
                std::lock_guard<std::mutex> lock(mutex_);
                slot.filled = true;
            }
            filled_.notify_one();
            if (last) return;
        }
    }

    const RayReader& reader_;
    std::vector<Slot> slots_;
    std::mutex mutex_;
    std::condition_variable filled_;
    std::vector<std::condition_variable> free_;  // one per thread, woken when its next slot is free
    uint64_t taken_ = 0;                         // chunks the caller has taken
    bool stopping_ = false;
    std::vector<std::thread> threads_;  // last: they start once everything above is ready
};

RayReader::RayReader(std::unique_ptr<RayDecoder> decoder, std::string path, RayReadOptions options)
    : decoder_(std::move(decoder)), path_(std::move(path)), options_(options) {
    header_ = decoder_->header();
    options_.chunk_size = std::max<size_t>(options_.chunk_size, 1);
}

RayReader::~RayReader() = default;  // stops the read-ahead thread first (ahead_ is the last member)

double RayReader::progress() const {
    uint64_t n = header_.ray_count;
    uint64_t done =
        std::max<uint64_t>(totals_.rays, rays_in_parts_.load(std::memory_order_relaxed));
    return n ? std::min(1.0, double(done) / double(n)) : 0.0;
}

bool RayReader::read(RayChunk& chunk) {
    if (!ahead_) ahead_ = std::make_unique<ReadAhead>(*this);
    RayTotals chunk_totals;
    if (ahead_->take(chunk, chunk_totals)) {
        totals_ += chunk_totals;
        return true;
    }
    finish();
    return false;
}

size_t RayReader::parts() const {
    if (!reopen_ || !decoder_->can_seek()) return 1;
    // Parts of at least 16 chunks: fewer would cost more in opening and threads than they save.
    const uint64_t least_rays_per_part = 16 * options_.chunk_size;
    return static_cast<size_t>(
        std::clamp<uint64_t>(header_.ray_count / least_rays_per_part, 1, kMaxParts));
}

void RayReader::read_in_parts(const std::function<void(size_t, const RayColumns&)>& visit,
                              const std::function<void(double)>& progress) {
    if (ahead_) throw std::logic_error("RayReader: read_in_parts() after read()");
    const size_t parts = this->parts();
    const uint64_t count = header_.ray_count;
    struct Part {
        RayTotals totals;
        std::exception_ptr error;
    };
    std::vector<Part> results(parts);
    std::atomic<size_t> next_part{0};
    // The lowest part that failed: later parts stop early, earlier ones go on (one of them may
    // hold an earlier bad ray, which is the one to report).
    std::atomic<size_t> failed{parts};
    auto record_failure = [&](size_t p) {
        results[p].error = std::current_exception();
        size_t seen = failed.load();
        while (p < seen && !failed.compare_exchange_weak(seen, p)) {
        }
    };
    auto read_part = [&](size_t p, RayDecoder& decoder, RayColumns& chunk, bool report_progress) {
        const uint64_t first = count * p / parts,
                       end = parts == 1 ? UINT64_MAX : count * (p + 1) / parts;
        if (parts > 1) decoder.seek(first);
        for (uint64_t next = first; next < end && failed.load(std::memory_order_relaxed) > p;) {
            if (!decoder.decode(chunk, static_cast<size_t>(
                                           std::min<uint64_t>(options_.chunk_size, end - next))))
                break;
            results[p].totals += validate(chunk);
            visit(p, chunk);
            next += chunk.size();
            rays_in_parts_.fetch_add(chunk.size(), std::memory_order_relaxed);
            if (report_progress && progress) progress(this->progress());
        }
    };
    // The calling thread reads with the decoder open_rays() made (which also serves a single
    // part) and reports progress; every other thread opens one of its own. A thread reads each
    // part it takes with its one decoder and chunk, seeking to the part's first ray.
    auto work = [&](bool calling_thread) {
        std::unique_ptr<RayDecoder> own;
        RayColumns chunk;
        for (size_t p; (p = next_part.fetch_add(1)) < parts;) {
            try {
                if (!calling_thread && !own) own = reopen_();
                read_part(p, calling_thread ? *decoder_ : *own, chunk, calling_thread);
            } catch (...) {
                record_failure(p);
            }
        }
    };
    std::vector<std::thread> helpers;
    const size_t threads =
        std::min<size_t>(parts, std::max(1u, std::thread::hardware_concurrency()));
    for (size_t t = 1; t < threads; ++t) helpers.emplace_back(work, false);
    work(true);
    for (std::thread& t : helpers) t.join();
    for (const Part& part : results) {
        if (part.error) std::rethrow_exception(part.error);
        totals_ += part.totals;  // in part order: the sums do not depend on the threads
    }
    finish();
}

void RayReader::finish() {
    if (totals_.rays == 0) fail(path_, "the file holds no rays");
    const bool no_light = (!header_.has_radiant || totals_.radiant <= 0) &&
                          (!header_.has_luminous || totals_.luminous <= 0);
    if (no_light) fail(path_, "every ray has zero flux: the file carries no light");
    if (totals_.zero_flux_rays)
        warnings_.push_back(
            fmt::format("{}: {} of {} rays have zero flux (kept; they carry no light)", path_,
                        totals_.zero_flux_rays, totals_.rays));
    if (options_.flux_policy == FluxPolicy::rays) {
        auto check = [&](bool present, double stated, double sum, const char* what,
                         const char* unit) {
            if (present && std::isfinite(stated) && stated > 0 && !totals_agree(stated, sum))
                warnings_.push_back(fmt::format(
                    "{}: the rays' {} flux sums to {:.7g} {} but the header states {:.7g} {}: "
                    "the rays are used (--trust header scales them to the header)",
                    path_, what, sum, unit, stated, unit));
        };
        check(header_.has_radiant, header_.stated_radiant, totals_.radiant, "radiant", "W");
        check(header_.has_luminous, header_.stated_luminous, totals_.luminous, "luminous", "lm");
    }
}

namespace {

// The validity rule, one predicate per value, each one comparison chain (false for NaN and
// infinities as well as out-of-range values); the fast test below and check_ray(), which says
// what is wrong, both use them. Bitwise & and | rather than && and ||: no branch per value.
inline bool finite_float(float v) { return std::abs(v) <= std::numeric_limits<float>::max(); }
inline bool flux_ok(float v) { return (v >= 0) & (v <= std::numeric_limits<float>::max()); }
// NaN means "unknown wavelength" in real files; anything else must be a positive wavelength.
inline bool wavelength_ok(float v) {
    return std::isnan(v) | ((v > 0) & (v <= std::numeric_limits<float>::max()));
}
inline bool spectrum_ok(int32_t index, int32_t tables) { return (index >= 0) & (index < tables); }

// The fast test every ray must pass; check_ray() says what is wrong with one that does not.
// Every ray of a valid file evaluates all of it.
struct RayTest {
    float min_length2, max_length2;  // |d| within [1 - tol, 1 + tol] as a test on |d|^2: no root
    // Which columns hold the file's values: a decoder fills the others with the unknown value
    // (docs/architecture.md, "The ray record and its header").
    bool radiant, luminous, wavelength, per_ray_table;
    int32_t tables;

    bool direction_ok(float dx, float dy, float dz) const {
        const float length2 = dx * dx + dy * dy + dz * dz;
        return (length2 >= min_length2) & (length2 <= max_length2);
    }
    bool passes(const Ray& r) const {
        return finite_float(r.origin.x) & finite_float(r.origin.y) & finite_float(r.origin.z) &
               direction_ok(r.direction.x, r.direction.y, r.direction.z) &
               ((!radiant) | flux_ok(r.radiant)) & ((!luminous) | flux_ok(r.luminous)) &
               ((!wavelength) | wavelength_ok(r.wavelength)) &
               ((!per_ray_table) | spectrum_ok(r.spectrum, tables));
    }
};

// Whether every ray passes: a loop per group of columns, each of which the compiler
// vectorises, and none over a column the file does not carry.
RAYSET_ALWAYS_INLINE bool all_pass_loops(const RayColumns& c, const RayTest& test) {
    const size_t n = c.size();
    const float *ox = c.ox.data(), *oy = c.oy.data(), *oz = c.oz.data();
    const float *dx = c.dx.data(), *dy = c.dy.data(), *dz = c.dz.data();
    int pass = 1;
    for (size_t i = 0; i < n; ++i)
        pass &= finite_float(ox[i]) & finite_float(oy[i]) & finite_float(oz[i]) &
                test.direction_ok(dx[i], dy[i], dz[i]);
    auto all_flux_ok = [n, &pass](const float* flux) {
        for (size_t i = 0; i < n; ++i) pass &= flux_ok(flux[i]);
    };
    if (test.radiant) all_flux_ok(c.radiant.data());
    if (test.luminous) all_flux_ok(c.luminous.data());
    if (test.wavelength) {
        const float* wavelength = c.wavelength.data();
        for (size_t i = 0; i < n; ++i) pass &= wavelength_ok(wavelength[i]);
    }
    if (test.per_ray_table) {
        const int32_t* spectrum = c.spectrum.data();
        for (size_t i = 0; i < n; ++i) pass &= spectrum_ok(spectrum[i], test.tables);
    }
    return pass;
}

// The fluxes scaled (a scale within float rounding of 1 leaves them as they are), summed, and
// the rays with no flux counted.
struct FluxColumns {
    float* flux[2];  // radiant, luminous
    bool present[2];
    double scale[2];
};

RAYSET_ALWAYS_INLINE RayTotals flux_totals_loops(const FluxColumns& c, size_t n) {
    for (int f = 0; f < 2; ++f)
        if (c.present[f] && float(c.scale[f]) != 1)
            for (size_t i = 0; i < n; ++i) c.flux[f][i] = float(double(c.flux[f][i]) * c.scale[f]);
    // Eight sums (ray i to sum i % 8, the last n % 8 rays to the first) added at the end: a
    // chain of dependent additions an eighth as long, in a loop the compiler vectorises.
    auto lane_sum = [n](const float* flux) {
        double lane[8] = {};
        size_t i = 0;
        for (; i + 8 <= n; i += 8)
            for (size_t l = 0; l < 8; ++l) lane[l] += flux[i + l];
        for (; i < n; ++i) lane[0] += flux[i];
        return std::accumulate(lane, lane + 8, 0.0);
    };
    RayTotals totals;
    if (c.present[0]) totals.radiant = lane_sum(c.flux[0]);
    if (c.present[1]) totals.luminous = lane_sum(c.flux[1]);
    // Counted 32 bits wide, a block at a time, which vectorises (64-bit counts would not).
    const bool radiant = c.present[0], luminous = c.present[1];
    const float *radiant_flux = c.flux[0], *luminous_flux = c.flux[1];
    for (size_t start = 0; start < n; start += size_t(1) << 30) {
        const size_t end = std::min(n, start + (size_t(1) << 30));
        uint32_t zero = 0;
        for (size_t i = start; i < end; ++i)
            zero += ((!radiant) | (radiant_flux[i] == 0)) & ((!luminous) | (luminous_flux[i] == 0));
        totals.zero_flux_rays += zero;
    }
    totals.rays = n;
    return totals;
}

// Both compiled for AVX2 too (converters/rays/simd.h).
#if RAYSET_HAVE_AVX2_TARGET
RAYSET_TARGET_AVX2 bool all_pass_avx2(const RayColumns& c, const RayTest& test) {
    return all_pass_loops(c, test);
}
RAYSET_TARGET_AVX2 RayTotals flux_totals_avx2(const FluxColumns& c, size_t n) {
    return flux_totals_loops(c, n);
}
#endif

bool all_pass(const RayColumns& c, const RayTest& test) {
#if RAYSET_HAVE_AVX2_TARGET
    if (cpu_has_avx2()) return all_pass_avx2(c, test);
#endif
    return all_pass_loops(c, test);
}

RayTotals flux_totals(const FluxColumns& c, size_t n) {
#if RAYSET_HAVE_AVX2_TARGET
    if (cpu_has_avx2()) return flux_totals_avx2(c, n);
#endif
    return flux_totals_loops(c, n);
}

}  // namespace

RayTotals RayReader::validate(RayColumns& chunk) const {
    const double tolerance = options_.direction_tolerance;
    const RayTest test{float((1 - tolerance) * (1 - tolerance)),
                       float((1 + tolerance) * (1 + tolerance)),
                       header_.has_radiant,
                       header_.has_luminous,
                       header_.spectral == SpectralKind::per_ray_wavelength,
                       header_.spectral == SpectralKind::per_ray_table,
                       static_cast<int32_t>(header_.spectral_tables.size())};
    const size_t n = chunk.size();
    // Nearly every chunk is valid: one pass finds out, without stopping at the first bad ray;
    // only a chunk that fails is walked again to report (or, if allowed, fix) its first bad ray.
    if (!all_pass(chunk, test))
        for (size_t i = 0; i < n; ++i)
            if (!test.passes(chunk.ray(i)))
                check_ray(chunk, i);  // throws, or normalises an accepted direction

    const FluxColumns flux{{chunk.radiant.data(), chunk.luminous.data()},
                           {header_.has_radiant, header_.has_luminous},
                           {radiant_scale_, luminous_scale_}};
    return flux_totals(flux, n);
}

// The slow path for a ray the fast test did not pass: says exactly what is wrong, or (for a
// direction the user allowed with --normalise) fixes it.
void RayReader::check_ray(RayColumns& chunk, size_t i) const {
    Ray r = chunk.ray(i);
    auto bad = [&](const std::string& what) {
        uint64_t index = chunk.first_index + i;
        fail(path_, decoder_->locate(index), fmt::format("ray {}: {}", index + 1, what));
    };
    if (!finite_float(r.origin.x) || !finite_float(r.origin.y) || !finite_float(r.origin.z))
        bad(fmt::format("origin ({}, {}, {}) is not a finite number", r.origin.x, r.origin.y,
                        r.origin.z));
    const Vec3f& d = r.direction;
    if (!finite_float(d.x) || !finite_float(d.y) || !finite_float(d.z))
        bad(fmt::format("direction ({}, {}, {}) is not a finite number", d.x, d.y, d.z));
    if (header_.has_radiant && !flux_ok(r.radiant))
        bad(fmt::format("radiant flux {} is not a non-negative number", r.radiant));
    if (header_.has_luminous && !flux_ok(r.luminous))
        bad(fmt::format("luminous flux {} is not a non-negative number", r.luminous));
    if (header_.spectral == SpectralKind::per_ray_wavelength && !wavelength_ok(r.wavelength))
        bad(fmt::format("wavelength {} nm is not a positive number (NaN would mean unknown)",
                        r.wavelength));
    const size_t tables = header_.spectral_tables.size();
    if (header_.spectral == SpectralKind::per_ray_table &&
        !spectrum_ok(r.spectrum, int32_t(tables)))
        bad(fmt::format("spectrum index {} is outside the file's {} spectral tables",
                        r.spectrum + 1, tables));
    const double length = std::sqrt(double(d.x) * d.x + double(d.y) * d.y + double(d.z) * d.z);
    if (std::abs(length - 1) > options_.direction_tolerance) {
        if (!options_.normalise_directions || length == 0)
            bad(fmt::format(
                "direction ({}, {}, {}) has length {:.6g}, not 1{}", d.x, d.y, d.z, length,
                length == 0 ? "" : " (--normalise accepts and renormalises such directions)"));
        r.direction = {float(d.x / length), float(d.y / length), float(d.z / length)};
        chunk.set(i, r);
    }
}

}  // namespace rayset
