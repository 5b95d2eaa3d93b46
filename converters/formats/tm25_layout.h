// Byte layout of an IES TM-25-13 ray file (see ../shared/formats.md), shared by the TM-25
// decoder (tm25.cpp) and encoder (tm25_encoder.cpp). Private to those two files.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace rayset::tm25 {

inline constexpr char kMagic[4] = {'T', 'M', '2', '5'};
inline constexpr int32_t kVersion = 2013;

// Offsets of the header fields.
inline constexpr uint64_t kVersionAt = 4;
inline constexpr uint64_t kCreationMethodAt = 8;
inline constexpr uint64_t kLuminousTotalAt = 12;
inline constexpr uint64_t kRadiantTotalAt = 16;
inline constexpr uint64_t kRayCountAt = 20;
inline constexpr uint64_t kDateAt = 28;
inline constexpr size_t kDateBytes = 28;
inline constexpr uint64_t kRayStartAt = 56;
inline constexpr uint64_t kSpectralIdAt = 60;
inline constexpr uint64_t kSingleWavelengthAt = 64;
inline constexpr uint64_t kMinWavelengthAt = 68;
inline constexpr uint64_t kMaxWavelengthAt = 72;
inline constexpr uint64_t kTableCountAt = 76;
inline constexpr uint64_t kAdditionalCountAt = 80;
inline constexpr uint64_t kTextSizeAt = 84;
inline constexpr uint64_t kReservedAt = 88;
inline constexpr uint64_t kFlagsAt = 256;
inline constexpr uint64_t kTextsAt = 288;
inline constexpr size_t kTextChars = 1000;  // code points per text field
inline constexpr size_t kTextCount = 9;
inline constexpr uint64_t kTablesAt = kTextsAt + kTextCount * kTextChars * 4;  // 36288
inline constexpr size_t kLabelChars = 128;   // 512 bytes of UTF-32
inline constexpr uint64_t kBlockAlign = 32;  // the spectral block and the additional text

// The eight data flags at byte 256, in file order.
enum Flag {
    position,
    direction,
    radiant,
    wavelength,
    luminous,
    stokes,
    tristimulus,
    spectrum_index,
    kFlagCount
};
using Flags = std::array<int32_t, kFlagCount>;

inline constexpr uint64_t flag_at(int flag) { return kFlagsAt + 4 * static_cast<uint64_t>(flag); }
inline const char* flag_name(int flag) {
    static const char* const names[kFlagCount] = {"position",    "direction",     "radiant flux",
                                                  "wavelength",  "luminous flux", "Stokes",
                                                  "tristimulus", "spectrum index"};
    return names[flag];
}

inline const char* text_name(size_t field) {
    static const char* const names[kTextCount] = {"name",
                                                  "manufacturer",
                                                  "model creator",
                                                  "ray-file creator",
                                                  "equipment/software",
                                                  "camera",
                                                  "operating conditions",
                                                  "additional info",
                                                  "data reference"};
    return names[field];
}

// Column of each item in a ray record (-1 when absent), in the order the format fixes.
struct Columns {
    int radiant = -1, wavelength = -1, luminous = -1, stokes = -1, tristimulus = -1, spectrum = -1,
        additional = -1;
    int count = 6;  // x y z kx ky kz always come first
};

inline Columns column_layout(const Flags& flags, int additional) {
    Columns c;
    auto take = [&c](bool on, int& at, int width) {
        if (on && width > 0) {
            at = c.count;
            c.count += width;
        }
    };
    take(flags[radiant], c.radiant, 1);
    take(flags[wavelength], c.wavelength, 1);
    take(flags[luminous], c.luminous, 1);
    take(flags[stokes], c.stokes, 6);  // S1 S2 S3 and the polarisation ellipse axis x y z
    take(flags[tristimulus], c.tristimulus, 2);
    take(flags[spectrum_index], c.spectrum, 1);
    take(true, c.additional, additional);
    return c;
}

// A byte count rounded up to the 32-byte blocks the spectral block and the text are padded to.
inline uint64_t padded(uint64_t bytes) {
    return (bytes + kBlockAlign - 1) / kBlockAlign * kBlockAlign;
}

// Why a spectral table cannot be used ("" if it can). bad_value is the offending value's index
// as the file interleaves them: 2k for the k-th wavelength, 2k + 1 for its weight.
std::string table_problem(const float* wavelength, const float* weight, size_t points,
                          size_t& bad_value);

}  // namespace rayset::tm25
