// IES LM-63 photometric files (1986, 1991, 1995, 2002, 2019): the file as written (IesFile, for
// round trips that keep every field, keyword order and TILT data) and its mapping to Photometry.
#pragma once

#include "converters/photometry/photometry.h"

#include <string>
#include <vector>

namespace rayset {

enum class IesVersion { lm63_1986, lm63_1991, lm63_1995, lm63_2002, lm63_2019 };

// TILT: how lamp output changes with the luminaire's tilt (for lamps whose output depends on
// their burning position). Kept in IesFile; Photometry has no place for it (see
// docs/formats/photometry.md).
struct IesTilt {
    enum class Kind { none, include, file };
    Kind kind = Kind::none;
    std::string file_name;  // Kind::file: the name after "TILT=", as written
    int lamp_to_luminaire_geometry =
        1;  // 1 vertical, 2 horizontal along 0-180, 3 horizontal along 90-270
    std::vector<double> angles_deg;
    std::vector<double> multipliers;
};

// One "[KEY] value" line and its "[MORE]" continuations (value lines joined with '\n'), in file
// order; keywords may repeat. key "" holds a free-text line (LM-63-1986 has no keywords).
struct IesKeyword {
    std::string key;
    std::string value;
};

struct IesFile {
    IesVersion version = IesVersion::lm63_2002;
    std::vector<IesKeyword> keywords;
    IesTilt tilt;
    int lamp_count = 1;
    double lumens_per_lamp = -1;               // -1: absolute photometry
    double multiplier = 1;                     // candela multiplier
    int photometric_type = 1;                  // 1 C, 2 B, 3 A
    int units = 2;                             // 1 feet, 2 metres
    double width = 0, length = 0, height = 0;  // luminous opening, file units; negative = round
    double ballast_factor = 1;
    // Ballast-lamp photometric factor before LM-63-2002, "future use" (1) in 2002, file
    // generation type in 2019 (e.g. 1.00001 undefined, 1.10000 accredited test lab).
    double generation = 1;
    double input_watts = 0;
    std::vector<double> vertical_deg;
    std::vector<double> horizontal_deg;
    std::vector<double> candela;  // as written, before the multiplier: [h * vertical + v]
};

// Reads any LM-63 version. TILT=<file> is read from the IES file's folder. Errors name the file
// and line and say what was expected.
IesFile read_ies(const std::string& path);

// Writes the version the IesFile says (1986 without a version line), numbers with the shortest
// text that reads back to the same double, lines wrapped at 80 columns, CRLF line ends.
void write_ies(const std::string& path, const IesFile& file);

// Photometry from an IES file: candela = value x multiplier (once; the ballast factor and the
// ballast-lamp factor are not applied, they stay in ballast_factor / IesFile), dimensions in
// metres, rated_lumens = lamps x lumens per lamp (NaN for absolute photometry), round = any
// dimension negative. Keywords: each key once, repeated keys' values joined with '\n' in file
// order; free-text lines under "OTHER".
Photometry ies_to_photometry(const IesFile& file);

// The IES file for a Photometry: LM-63-2002 (or 2019), units metres, multiplier 1, keywords in
// LM-63 order then the rest alphabetically. Type C bilateral 90..270 data is unfolded to
// 0..360 (2002 and 2019 do not allow 90..270). `path` names the target in error messages.
IesFile ies_from_photometry(const Photometry& photometry, const std::string& path,
                            IesVersion version = IesVersion::lm63_2002);

}  // namespace rayset
