// IES TM-25-13 ray files: detection and decoding (the encoder is in tm25_encoder.cpp).
// The whole structure is checked when the file is opened, so that a wrong ray count or a
// contradictory flag is reported before any ray is handed out.
#include "converters/formats/codecs.h"
#include "converters/formats/tm25_layout.h"
#include "converters/rays/io.h"
#include "converters/rays/simd.h"
#include "core/text_encoding.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstring>
#if defined(__SSE2__)
#include <xmmintrin.h>
#endif

namespace rayset {
namespace tm25 {

std::string table_problem(const float* wavelength, const float* weight, size_t points,
                          size_t& bad_value) {
    for (size_t k = 0; k < points; ++k) {
        bad_value = 2 * k;
        if (!(std::isfinite(wavelength[k]) && wavelength[k] > 0))
            return "wavelength " + format_float(wavelength[k]) + " nm is not a positive number";
        if (k > 0 && !(wavelength[k] > wavelength[k - 1]))
            return "wavelength " + format_float(wavelength[k]) +
                   " nm does not ascend from the point before (" + format_float(wavelength[k - 1]) +
                   " nm)";
        bad_value = 2 * k + 1;
        if (!(std::isfinite(weight[k]) && weight[k] >= 0))
            return "weight " + format_float(weight[k]) + " is not a number >= 0";
    }
    return {};
}

}  // namespace tm25

namespace {

using namespace tm25;

class Tm25Decoder final : public RayDecoder {
public:
    explicit Tm25Decoder(const std::string& path) : in_(path) {
        read_fixed_header();
        check_flags();
        read_texts();
        read_tables();
        read_labels_and_text();
        check_size();
    }

    bool decode(RayColumns& chunk, size_t max_rays) override;
    Location locate(uint64_t index) const override {
        return Location::byte(data_start_ + index * record_bytes_);
    }
    bool can_seek() const override { return true; }
    void seek(uint64_t index) override { in_.seek(locate(index).value), next_ = index; }

private:
    void read_fixed_header();
    void check_flags();
    void read_texts();
    void read_tables();
    void read_labels_and_text();
    void check_size();
    std::string text(size_t chars, const char* what);
    void unpack(const float* records, size_t n, RayColumns& chunk, size_t at) const;
    RAYSET_ALWAYS_INLINE void unpack_loops(const float* records, size_t n, RayColumns& chunk,
                                           size_t at) const;
#if RAYSET_HAVE_AVX2_TARGET
    RAYSET_TARGET_AVX2 void unpack_avx2(const float* records, size_t n, RayColumns& chunk,
                                        size_t at) const {
        unpack_loops(records, n, chunk, at);
    }
#endif
    [[noreturn]] void fail_spectrum_index(uint64_t index, float value) const;

    BinaryInput in_;
    Flags flags_{};
    int32_t spectral_id_ = 0, table_count_ = 0, additional_count_ = 0, text_bytes_ = 0;
    Columns columns_;
    int front_extras_ = 0;  // Stokes and tristimulus columns, contiguous in the record
    uint64_t data_start_ = 0, record_bytes_ = 0, next_ = 0;
    std::vector<float> buffer_;
};

void Tm25Decoder::read_fixed_header() {
    char magic[4];
    in_.read(magic, 4, "the TM-25 magic");
    if (std::memcmp(magic, kMagic, 4) != 0)
        in_.fail_at(0, "not an IES TM-25 ray file: it does not start with 'TM25'");
    // The fields are read in file order; no seeking, which would discard the stdio buffer.
    auto version = in_.read<int32_t>("the version");
    // Only TM-25-13 is known; a later revision with another layout would fail the exact size
    // check at the end, so other plausible years are read with the 2013 layout.
    if (version < 1 || version > 9999)
        in_.fail_at(kVersionAt,
                    "version " + std::to_string(version) + " is not a year: the header is corrupt");
    header_.format = RayFormat::tm25;
    header_.unit = LengthUnit::mm;
    header_.creation_method = in_.read<int32_t>("the creation method");
    header_.stated_luminous = in_.read<float>("the total luminous flux");
    header_.stated_radiant = in_.read<float>("the total radiant flux");
    header_.ray_count = in_.read<uint64_t>("the number of rays");
    char date[kDateBytes];
    in_.read(date, kDateBytes, "the creation date");
    header_.creation_date.assign(date, strnlen(date, kDateBytes));
    auto ray_start = in_.read<int32_t>("the ray start position");
    if (ray_start < 0 || ray_start > 7)
        in_.fail_at(kRayStartAt,
                    "ray start position " + std::to_string(ray_start) + " is outside 0..7");
    spectral_id_ = in_.read<int32_t>("the spectral data id");
    if (spectral_id_ < 0 || spectral_id_ > 4)
        in_.fail_at(kSpectralIdAt,
                    "spectral data id " + std::to_string(spectral_id_) + " is outside 0..4");
    header_.spectral = static_cast<SpectralKind>(spectral_id_);
    header_.single_wavelength = in_.read<float>("the single wavelength");
    header_.min_wavelength = in_.read<float>("the minimum wavelength");
    header_.max_wavelength = in_.read<float>("the maximum wavelength");
    if (spectral_id_ == 1 &&
        !(std::isfinite(header_.single_wavelength) && header_.single_wavelength > 0))
        in_.fail_at(
            kSingleWavelengthAt,
            "spectral data id 1 (single wavelength) needs a positive wavelength here, not " +
                format_float(header_.single_wavelength));
    table_count_ = in_.read<int32_t>("the number of spectral tables");
    additional_count_ = in_.read<int32_t>("the number of additional ray items");
    text_bytes_ = in_.read<int32_t>("the size of the additional text");
    // Reserved bytes are not checked: a later revision may use them, and the exact size check
    // catches layouts that differ.
    char reserved[kFlagsAt - kReservedAt];
    in_.read(reserved, sizeof reserved, "the reserved header bytes");
    in_.read(flags_.data(), sizeof flags_, "the data flags");
}

void Tm25Decoder::check_flags() {
    for (int f = 0; f < kFlagCount; ++f)
        if (flags_[f] != 0 && flags_[f] != 1)
            in_.fail_at(flag_at(f), std::string(flag_name(f)) + " flag is " +
                                        std::to_string(flags_[f]) + ", not 0 or 1");
    for (int f : {position, direction})
        if (!flags_[f])
            in_.fail_at(flag_at(f),
                        std::string(flag_name(f)) + " flag is 0 but every TM-25 ray needs it");
    auto at = [](int f) { return " (byte " + std::to_string(flag_at(f)) + ")"; };
    if (!flags_[radiant] && !flags_[luminous])
        in_.fail_at(flag_at(radiant), "neither the radiant flux flag nor the luminous flux flag" +
                                          at(luminous) + " is set: the rays carry no flux");
    std::string id = "spectral data id " + std::to_string(spectral_id_);
    if ((spectral_id_ == 2 || spectral_id_ == 4) && (!flags_[radiant] || flags_[luminous]))
        in_.fail_at(kSpectralIdAt, id + " needs the radiant flux flag" + at(radiant) +
                                       " and no luminous flux flag" + at(luminous));
    if (spectral_id_ == 2 && !flags_[wavelength])
        in_.fail_at(kSpectralIdAt, id + " needs the wavelength flag" + at(wavelength));
    // Per-ray wavelengths under another id contradict the id; no writer is known to do it.
    if (spectral_id_ != 2 && flags_[wavelength])
        in_.fail_at(flag_at(wavelength),
                    "wavelength flag is set but per-ray wavelengths need spectral data id 2, not " +
                        std::to_string(spectral_id_) + " (byte 60)");
    if ((spectral_id_ == 4) != (flags_[spectrum_index] == 1))
        in_.fail_at(flag_at(spectrum_index),
                    "spectrum index flag is " + std::to_string(flags_[spectrum_index]) +
                        " but the spectral data id (byte 60) is " + std::to_string(spectral_id_) +
                        ": the flag must be set exactly when the id is 4");
    if (flags_[stokes] && !flags_[radiant])
        in_.fail_at(flag_at(stokes), "Stokes flag needs the radiant flux flag" + at(radiant));
    if (flags_[tristimulus] && !flags_[luminous])
        in_.fail_at(flag_at(tristimulus),
                    "tristimulus flag needs the luminous flux flag" + at(luminous));
    if (flags_[tristimulus] && spectral_id_ != 0)
        in_.fail_at(flag_at(tristimulus),
                    "tristimulus flag needs spectral data id 0 (byte 60), not " +
                        std::to_string(spectral_id_));
    if (additional_count_ < 0)
        in_.fail_at(kAdditionalCountAt, "number of additional ray items is negative (" +
                                            std::to_string(additional_count_) + ")");
    // Bounded before the record layout is computed from it: each item has a 512-byte label.
    if (static_cast<uint64_t>(additional_count_) * 4 * kLabelChars > in_.remaining() ||
        additional_count_ > INT32_MAX - 32)
        in_.fail_at(
            kAdditionalCountAt,
            std::to_string(additional_count_) +
                " additional ray items need more column labels than the rest of the file holds");
    header_.has_radiant = flags_[radiant];
    header_.has_luminous = flags_[luminous];
    columns_ = column_layout(flags_, additional_count_);
    record_bytes_ = 4 * static_cast<uint64_t>(columns_.count);
    front_extras_ = 6 * flags_[stokes] + 2 * flags_[tristimulus];
    auto add = [this](ExtraKind kind, const char* label) {
        header_.extras.push_back({kind, label});
    };
    if (flags_[stokes]) {
        add(ExtraKind::stokes_s1, "Stokes S1");
        add(ExtraKind::stokes_s2, "Stokes S2");
        add(ExtraKind::stokes_s3, "Stokes S3");
        add(ExtraKind::ellipse_x, "polarisation ellipse x");
        add(ExtraKind::ellipse_y, "polarisation ellipse y");
        add(ExtraKind::ellipse_z, "polarisation ellipse z");
    }
    if (flags_[tristimulus]) {
        add(ExtraKind::tristimulus_x, "tristimulus X");
        add(ExtraKind::tristimulus_z, "tristimulus Z");
    }
}

std::string hex(uint32_t value) {
    char buffer[16];
    std::snprintf(buffer, sizeof buffer, "0x%X", value);
    return buffer;
}

std::string Tm25Decoder::text(size_t chars, const char* what) {
    std::u32string raw(chars, U'\0');
    uint64_t at = in_.offset();
    in_.read(raw.data(), 4 * chars, what);
    std::string out;
    size_t bad = utf32_to_utf8(raw.data(), chars, out);
    if (bad != std::string::npos)
        in_.fail_at(at + 4 * bad, std::string(what) + " holds " + hex(raw[bad]) +
                                      ", which is not a Unicode code point (UTF-32 expected)");
    return out;
}

void Tm25Decoder::read_texts() {
    for (size_t k = 0; k < kTextCount; ++k)
        header_.text[k] =
            text(kTextChars, (std::string("the text field '") + text_name(k) + "'").c_str());
}

void Tm25Decoder::read_tables() {
    // Each table takes at least 12 bytes; this bounds the count before anything is allocated.
    if (table_count_ < 0 || static_cast<uint64_t>(table_count_) * 12 > in_.remaining())
        in_.fail_at(kTableCountAt, "number of spectral tables " + std::to_string(table_count_) +
                                       " is negative or more than the rest of the file can hold");
    if ((spectral_id_ == 3 || spectral_id_ == 4) && table_count_ < 1)
        in_.fail_at(kTableCountAt, "spectral data id " + std::to_string(spectral_id_) +
                                       " (byte 60) needs spectral tables, but there are none");
    for (int32_t t = 0; t < table_count_; ++t) {
        uint64_t at = in_.offset();
        auto points = in_.read<int32_t>("the point count of a spectral table");
        if (points < 1 || static_cast<uint64_t>(points) * 8 > in_.remaining())
            in_.fail_at(at, "spectral table " + std::to_string(t + 1) + " has " +
                                std::to_string(points) +
                                " points: not positive or more than the rest of the file holds");
        std::vector<float> pairs(2 * static_cast<size_t>(points));
        in_.read(pairs.data(), 4 * pairs.size(), "a spectral table");
        SpectralTable table;
        table.wavelength.resize(points);
        table.weight.resize(points);
        for (int32_t k = 0; k < points; ++k) {
            table.wavelength[k] = pairs[2 * k];
            table.weight[k] = pairs[2 * k + 1];
        }
        size_t bad = 0;
        std::string problem =
            table_problem(table.wavelength.data(), table.weight.data(), table.weight.size(), bad);
        if (!problem.empty())
            in_.fail_at(at + 4 + 4 * bad, "spectral table " + std::to_string(t + 1) + ", point " +
                                              std::to_string(bad / 2 + 1) + ": " + problem);
        header_.spectral_tables.push_back(std::move(table));
    }
    char padding[kBlockAlign];
    in_.read(padding, padded(in_.offset() - kTablesAt) - (in_.offset() - kTablesAt),
             "the padding of the spectral tables");
}

void Tm25Decoder::read_labels_and_text() {
    for (int32_t k = 0; k < additional_count_; ++k)
        header_.extras.push_back(
            {ExtraKind::additional, text(kLabelChars, "an additional column label")});
    if (text_bytes_ < 0 || text_bytes_ % kBlockAlign != 0 ||
        static_cast<uint64_t>(text_bytes_) > in_.remaining())
        in_.fail_at(
            kTextSizeAt,
            "additional text size " + std::to_string(text_bytes_) +
                " is negative, not a multiple of 32 or more than the rest of the file holds");
    header_.additional_text = text(static_cast<size_t>(text_bytes_) / 4, "the additional text");
    data_start_ = in_.offset();
}

void Tm25Decoder::check_size() {
    uint64_t count = header_.ray_count;
    uint64_t size = in_.size();
    uint64_t room = size - data_start_;
    std::string stated =
        std::to_string(count) + " rays of " + std::to_string(record_bytes_) + " bytes";
    if (count > room / record_bytes_) {
        uint64_t max = UINT64_MAX;
        std::string needed = count > (max - data_start_) / record_bytes_
                                 ? "more than " + std::to_string(max)
                                 : std::to_string(data_start_ + count * record_bytes_);
        in_.fail_at(kRayCountAt, "the header states " + stated + " from byte " +
                                     std::to_string(data_start_) + ", a file of " + needed +
                                     " bytes, but the file has " + std::to_string(size) +
                                     " bytes: it is truncated or the ray count is wrong");
    }
    uint64_t end = data_start_ + count * record_bytes_;
    if (end != size)
        in_.fail_at(end, "the " + stated +
                             " the header states (byte 20) end here, but the file goes on for " +
                             std::to_string(size - end) +
                             " more bytes: the ray count is wrong or data was appended");
}

bool Tm25Decoder::decode(RayColumns& chunk, size_t max_rays) {
    chunk.first_index = next_;
    size_t n = static_cast<size_t>(std::min<uint64_t>(max_rays, header_.ray_count - next_));
    if (n == 0) {
        chunk.clear();
        return false;
    }
    // No clear(): every value of every ray is overwritten, and a chunk reused at the same size
    // then costs nothing to size.
    chunk.resize(n);
    chunk.extra.resize(n * header_.extras.size());
    // Reads of about 128 KiB, which BinaryInput passes straight from the file into a buffer
    // that stays in cache (L2) while it is unpacked: 1 MiB blocks were measured 4x slower.
    const size_t block_rays = std::max<size_t>(1, (size_t(128) << 10) / record_bytes_);
    for (size_t done = 0; done < n;) {
        size_t block = std::min(n - done, block_rays);
        buffer_.resize(block * columns_.count);
        in_.read(buffer_.data(), block * record_bytes_, "the ray records");
        unpack(buffer_.data(), block, chunk, done);
        done += block;
    }
    next_ += n;
    return true;
}

void Tm25Decoder::fail_spectrum_index(uint64_t index, float value) const {
    const std::string tables = std::to_string(header_.spectral_tables.size());
    in_.fail_at(locate(index).value + 4 * columns_.spectrum,
                "ray " + std::to_string(index + 1) + ": spectrum index " + format_float(value) +
                    " is not a table number 1.." + tables + " (the file has " + tables +
                    " spectral tables, byte 76)");
}

// The first eight values of records of `count` >= 7 floats into columns, four records at a
// time: two loads and a 4 x 4 transpose in registers instead of a load and a store per value.
// The first six (origin, direction) are always kept, the seventh and eighth where kSeventh and
// kEighth say (which column is kept is a template argument so that the loop tests nothing).
// Returns how many records it did; it stops early enough that reading eight values never
// passes the end of the last record.
template <bool kSeventh, bool kEighth>
RAYSET_ALWAYS_INLINE size_t unpack_leading(const float* records, size_t n, size_t count,
                                           float* const to[8]) {
    size_t i = 0;
#if defined(__SSE2__)
    for (; i + 5 <= n; i += 4) {
        const float* r = records + i * count;
        __m128 a = _mm_loadu_ps(r), b = _mm_loadu_ps(r + count), c = _mm_loadu_ps(r + 2 * count),
               d = _mm_loadu_ps(r + 3 * count);
        _MM_TRANSPOSE4_PS(a, b, c, d);
        _mm_storeu_ps(to[0] + i, a), _mm_storeu_ps(to[1] + i, b), _mm_storeu_ps(to[2] + i, c),
            _mm_storeu_ps(to[3] + i, d);
        a = _mm_loadu_ps(r + 4), b = _mm_loadu_ps(r + count + 4),
        c = _mm_loadu_ps(r + 2 * count + 4), d = _mm_loadu_ps(r + 3 * count + 4);
        _MM_TRANSPOSE4_PS(a, b, c, d);
        _mm_storeu_ps(to[4] + i, a), _mm_storeu_ps(to[5] + i, b);
        if constexpr (kSeventh) _mm_storeu_ps(to[6] + i, c);
        if constexpr (kEighth) _mm_storeu_ps(to[7] + i, d);
    }
#endif
    return i;
}

RAYSET_ALWAYS_INLINE size_t unpack_leading(const float* records, size_t n, size_t count,
                                           float* const to[8]) {
    if (to[6])
        return to[7] ? unpack_leading<true, true>(records, n, count, to)
                     : unpack_leading<true, false>(records, n, count, to);
    return to[7] ? unpack_leading<false, true>(records, n, count, to)
                 : unpack_leading<false, false>(records, n, count, to);
}

// Records to columns, straight from the read buffer: positions, directions and whatever the
// record has next in one pass (unpack_leading), the other columns one strided loop each.
// Compiled for AVX2 too (converters/rays/simd.h): its fills and the transposes' moves take fewer
// instructions.
void Tm25Decoder::unpack(const float* records, size_t n, RayColumns& chunk, size_t at) const {
#if RAYSET_HAVE_AVX2_TARGET
    if (cpu_has_avx2()) return unpack_avx2(records, n, chunk, at);
#endif
    unpack_loops(records, n, chunk, at);
}

RAYSET_ALWAYS_INLINE void Tm25Decoder::unpack_loops(const float* records, size_t n,
                                                    RayColumns& chunk, size_t at) const {
    const size_t count = columns_.count;
    float* leading[8] = {chunk.ox.data() + at,
                         chunk.oy.data() + at,
                         chunk.oz.data() + at,
                         chunk.dx.data() + at,
                         chunk.dy.data() + at,
                         chunk.dz.data() + at,
                         nullptr,
                         nullptr};
    struct Optional {
        int offset;
        float* to;
    } optional[3] = {{columns_.radiant, chunk.radiant.data() + at},
                     {columns_.luminous, chunk.luminous.data() + at},
                     {columns_.wavelength, chunk.wavelength.data() + at}};
    for (const Optional& column : optional)
        if (column.offset == 6 || column.offset == 7) leading[column.offset] = column.to;
    for (size_t i = unpack_leading(records, n, count, leading); i < n; ++i)
        for (int k = 0; k < 8; ++k)
            if (leading[k]) leading[k][i] = records[i * count + k];
    for (const Optional& column : optional) {
        if (column.offset < 0) std::fill(column.to, column.to + n, kUnknown);
        if (column.offset > 7)
            for (size_t i = 0; i < n; ++i) column.to[i] = records[i * count + column.offset];
    }
    int32_t* spectrum = chunk.spectrum.data() + at;
    if (columns_.spectrum < 0) {
        std::fill(spectrum, spectrum + n, -1);
    } else {
        // TM-25 numbers the tables from 1, as floats; an index that is not one of them is an error.
        const float tables = static_cast<float>(header_.spectral_tables.size());
        const float* from = records + columns_.spectrum;
        for (size_t i = 0; i < n; ++i) {
            const float index = from[i * count];
            if (!(index >= 1 && index <= tables && index == std::floor(index)))
                fail_spectrum_index(chunk.first_index + at + i, index);
            spectrum[i] = static_cast<int32_t>(index) - 1;
        }
    }
    const size_t front = front_extras_, additional = additional_count_, extras = front + additional;
    if (extras == 0) return;
    const int front_at = columns_.stokes >= 0 ? columns_.stokes : columns_.tristimulus;
    for (size_t i = 0; i < n; ++i) {
        const float* r = records + i * count;
        float* e = chunk.extra.data() + (at + i) * extras;
        if (front) std::memcpy(e, r + front_at, 4 * front);
        if (additional) std::memcpy(e + front, r + columns_.additional, 4 * additional);
    }
}

}  // namespace

bool sniff_tm25(const Head& head, uint64_t size) {
    return head.size() >= 4 && std::memcmp(head.data(), tm25::kMagic, 4) == 0;
}

std::unique_ptr<RayDecoder> open_tm25(const std::string& path) {
    return std::make_unique<Tm25Decoder>(path);
}

}  // namespace rayset
