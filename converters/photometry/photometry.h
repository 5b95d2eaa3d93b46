// Far-field photometry as IES LM-63 and EULUMDAT describe it: luminous intensity (cd) on a
// grid of (horizontal, vertical) angles of one photometric type. The common form both codecs
// read into and write from, and what far-field computation produces.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace rayset {

enum class PhotometricType { C = 1, B = 2, A = 3 };  // IES numbering

// Angle conventions, as LM-63 defines them:
//  type C: vertical = gamma from nadir (0) to zenith (180) around the vertical axis -z of the
//          luminaire... see docs/architecture.md "Photometric frames" for our axes;
//          horizontal = C-plane angle, counter-clockwise seen from above.
//  types A and B: vertical = elevation -90..90, horizontal = -90..90 (or 0..90 when symmetric).
struct Photometry {
    PhotometricType type = PhotometricType::C;
    std::vector<double> vertical_deg;    // ascending
    std::vector<double> horizontal_deg;  // ascending, as stored (may cover only a symmetric part)
    std::vector<double> candela;         // absolute cd, candela[h * vertical_deg.size() + v]

    // Lamp data. rated_lumens is the total rated lamp flux (lamps x lumens per lamp); NaN for
    // absolute photometry (LM-63 lumens -1, EULUMDAT negative lamp count); writers treat any
    // value not above zero as absolute.
    int lamp_count = 1;
    double rated_lumens = -1;
    double input_watts = 0;
    double ballast_factor = 1;

    // Luminous opening in metres: width (across C90-C270), length (along C0-C180), height.
    // round = true for a circular/spherical opening (IES negative dimensions).
    double width_m = 0, length_m = 0, height_m = 0;
    bool round = false;

    // Descriptive text: IES keywords ("TEST", "MANUFAC", "LUMCAT", "LUMINAIRE", ...) and the
    // EULUMDAT header lines map onto these keys; see ies.h and eulumdat.h for the mapping.
    std::map<std::string, std::string> keywords;

    size_t index(size_t h, size_t v) const { return h * vertical_deg.size() + v; }

    // Intensity in cd toward (horizontal, vertical) in degrees, over the full sphere, with the
    // stored symmetry unfolded and bilinear interpolation between grid angles.
    double intensity(double horizontal_deg, double vertical_deg) const;

    // Luminous flux in lm: the intensity integrated over the sphere (trapezoidal in angle
    // times exact solid-angle weights of each band).
    double total_flux() const;

    // Largest candela value on the grid.
    double max_candela() const;
};

enum class PhotometryFormat { ies, eulumdat };

Photometry read_photometry(const std::string& path);  // detects IES or EULUMDAT by content
PhotometryFormat detect_photometry_format(const std::string& path);
void write_photometry(const std::string& path, const Photometry& photometry,
                      PhotometryFormat format);

}  // namespace rayset
