// EULUMDAT (.ldt) photometric files: the file as written (EulumdatFile, every field kept for
// round trips) and its mapping to Photometry.
#pragma once

#include "converters/photometry/photometry.h"

#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace rayset {

// One standard set of lamps (lines 27-32 of a one-set file).
struct EulumdatLampSet {
    int count = 1;  // negative: absolute photometry
    std::string type;
    double lumens = 1000;   // total flux of the set's lamps
    std::string color;      // colour appearance / temperature, free text
    std::string rendering;  // colour rendering group / index, free text
    double watts = 0;       // including ballast
};

struct EulumdatFile {
    std::string company;  // line 1
    int ityp =
        1;  // 1 point source, vertical-axis symmetry; 2 linear; 3 point source, other symmetry
    int isym = 0;   // 0 none, 1 vertical axis, 2 plane C0-C180, 3 plane C90-C270, 4 both planes
    int mc = 0;     // number of C planes in 0..360
    double dc = 0;  // C-plane spacing, 0 if not equidistant
    int ng = 0;     // number of gamma angles
    double dg = 0;  // gamma spacing, 0 if not equidistant
    std::string report_number, luminaire_name, luminaire_number, file_name,
        date_user;  // lines 8-12
    double luminaire_length_mm = 0, luminaire_width_mm = 0,
           luminaire_height_mm = 0;                        // width 0: round
    double luminous_length_mm = 0, luminous_width_mm = 0;  // width 0: round
    std::array<double, 4> luminous_height_mm{};            // at C0, C90, C180, C270
    double downward_flux_percent = 0;                      // DFF
    double light_output_ratio_percent = 0;                 // LORL
    double conversion_factor = 1;                          // applied to the intensities
    double tilt_deg = 0;                                   // tilt during measurement
    std::vector<EulumdatLampSet> lamp_sets;
    std::array<double, 10> direct_ratios{};  // for room indices 0.6 .. 5
    std::vector<double> c_angles_deg;        // all mc
    std::vector<double> gamma_angles_deg;    // ng
    std::vector<double> intensities;         // cd/klm as written: stored planes (see isym) x ng
};

// Number of C planes stored for a symmetry: 0: mc; 1: 1; 2 and 3: mc/2 + 1; 4: mc/4 + 1. Isym 3
// stores C270 .. C360=C0 .. C90, starting at C-angle index 3mc/4 (Stockmar 1990).
size_t eulumdat_stored_planes(int isym, int mc);

// Reads an EULUMDAT file; decimal commas are accepted. Errors name the file and line.
EulumdatFile read_eulumdat(const std::string& path);

// Writes one value per line, CRLF line ends, numbers with the shortest text that reads back
// to the same double.
void write_eulumdat(const std::string& path, const EulumdatFile& file);

// Whether the start of a file reads as EULUMDAT (lines 2-7: Ityp, Isym, Mc, Dc, Ng, Dg).
bool looks_like_eulumdat(std::string_view head);

// Photometry from an EULUMDAT file. Intensity in cd = value x conversion factor x |lumens of lamp
// set 1| / 1000; further lamp sets are alternative equipment, not added. A negative lamp count
// means absolute photometry: set 1's lumens are then the luminaire's flux, rated_lumens is NaN.
// The luminous area gives the opening (width 0 = round, diameter = length), height = the largest
// of the four luminous heights. Isym 3 planes become the horizontal angles 90..270 (the mirror
// images 180 - C of the stored C270..C90). Text lines map to keywords: line 1 MANUFAC, 8 TEST,
// 9 LUMINAIRE, 10 LUMCAT, 12 ISSUEDATE, set 1's type LAMP; fields IES has no place for go to
// "_LDT_..." keywords (listed in docs/formats/photometry.md) so that LDT -> IES -> LDT keeps them.
Photometry eulumdat_to_photometry(const EulumdatFile& file);

// The EULUMDAT file for type C Photometry (types A and B fail: EULUMDAT has no such frame).
// Isym is the most compact one the data allows (1, 4, 2, 3, else 0; mirror planes compared
// exactly), so data unfolded by an IES round trip gets its Isym back. DFF and LORL come from the
// _LDT_ keywords when present, else from the intensities; line 11 is the file name of `path`.
EulumdatFile eulumdat_from_photometry(const Photometry& photometry, const std::string& path);

}  // namespace rayset
