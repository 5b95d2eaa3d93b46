// Photometry: intensity lookup with the stored symmetry unfolded, flux by quadrature, and the
// format-neutral read/detect/write entry points (IES in ies.cpp, EULUMDAT in eulumdat.cpp).
#include "converters/photometry/photometry.h"

#include "converters/photometry/eulumdat.h"
#include "converters/photometry/ies.h"
#include "converters/rays/io.h"
#include "core/error.h"

#include <algorithm>
#include <cmath>
#include <string_view>

namespace rayset {

namespace {

constexpr double pi = 3.14159265358979323846;
constexpr double deg = pi / 180.0;

// A plane of the unfolded distribution: its angle and the stored plane whose values it carries.
struct Plane {
    double angle;
    size_t index;
};

void check_grid(const Photometry& p) {
    if (p.vertical_deg.empty() || p.horizontal_deg.empty())
        throw Error("photometry: no angles (" + std::to_string(p.vertical_deg.size()) +
                    " vertical, " + std::to_string(p.horizontal_deg.size()) + " horizontal)");
    if (p.candela.size() != p.vertical_deg.size() * p.horizontal_deg.size())
        throw Error("photometry: " + std::to_string(p.candela.size()) + " candela values for " +
                    std::to_string(p.vertical_deg.size()) + " x " +
                    std::to_string(p.horizontal_deg.size()) + " angles");
}

double wrap_360(double a) {
    a = std::fmod(a, 360.0);
    return a < 0 ? a + 360.0 : a;
}

enum class CSymmetry { quadrant, bilateral_0_180, bilateral_90_270, none };

// LM-63 type C symmetries from the horizontal angles (more than one): 0..90 = quadrant (mirror in
// the 0-180 and 90-270 planes), 0..180 = bilateral about 0-180, 90..270 = bilateral about 90-270,
// anything else = no symmetry. A single plane is axial.
CSymmetry c_symmetry(const std::vector<double>& h) {
    if (h.front() == 0 && h.back() == 90) return CSymmetry::quadrant;
    if (h.front() == 0 && h.back() == 180) return CSymmetry::bilateral_0_180;
    if (h.front() == 90 && h.back() == 270) return CSymmetry::bilateral_90_270;
    return CSymmetry::none;
}

// Type C without symmetry: the planes before the one that closes the circle. A closing plane
// (C360 after C0) is C0 again; LM-63 requires the same values and C0's are the ones used, so
// that a table and its EULUMDAT form (which cannot hold C360) have the same intensities.
size_t open_planes(const std::vector<double>& h) {
    size_t n = h.size();
    while (n > 1 && h[n - 1] >= h.front() + 360) --n;
    return n;
}

// Type C: the planes around the full circle, from the first angle a0 to a0 + 360 inclusive (the
// last entry closes the circle); h has more than one angle.
std::vector<Plane> unfold_type_c(const std::vector<double>& h) {
    std::vector<Plane> planes;
    const size_t n = h.size();
    auto add = [&](double angle, size_t index) { planes.push_back({wrap_360(angle), index}); };
    CSymmetry symmetry = c_symmetry(h);
    if (symmetry == CSymmetry::quadrant) {
        for (size_t i = 0; i < n; ++i) {
            add(h[i], i);
            add(180 - h[i], i);
            add(180 + h[i], i);
            add(360 - h[i], i);
        }
    } else if (symmetry == CSymmetry::bilateral_0_180) {
        for (size_t i = 0; i < n; ++i) {
            add(h[i], i);
            add(360 - h[i], i);
        }
    } else if (symmetry == CSymmetry::bilateral_90_270) {
        for (size_t i = 0; i < n; ++i) {
            add(h[i], i);
            add(180 - h[i], i);
        }
    } else {
        for (size_t i = 0; i < open_planes(h); ++i) planes.push_back({h[i], i});
        planes.push_back({h.front() + 360, 0});
        return planes;
    }
    // Mirror images of the planes on a mirror plane coincide with them: keep one of each.
    std::stable_sort(planes.begin(), planes.end(),
                     [](const Plane& a, const Plane& b) { return a.angle < b.angle; });
    planes.erase(std::unique(planes.begin(), planes.end(),
                             [](const Plane& a, const Plane& b) { return a.angle == b.angle; }),
                 planes.end());
    planes.push_back({planes.front().angle + 360, planes.front().index});
    return planes;
}

// Types A and B: the horizontal (lateral) planes from the first to the last angle; 0..90 is
// mirrored to -90..90 (lateral symmetry).
std::vector<Plane> unfold_type_ab(const std::vector<double>& h) {
    std::vector<Plane> planes;
    const size_t n = h.size();
    if (n > 1 && h.front() == 0) {
        for (size_t i = n; i-- > 1;) planes.push_back({-h[i], i});
    }
    for (size_t i = 0; i < n; ++i) planes.push_back({h[i], i});
    return planes;
}

// Index i and fraction t with x between a[i] and a[i + 1]; a has at least 2 entries and
// a.front() <= x <= a.back().
void locate(const std::vector<double>& a, double x, size_t& i, double& t) {
    size_t hi = static_cast<size_t>(std::upper_bound(a.begin(), a.end(), x) - a.begin());
    i = std::min(hi == 0 ? 0 : hi - 1, a.size() - 2);
    t = (x - a[i]) / (a[i + 1] - a[i]);
}

// Linear interpolation along the vertical angles of stored plane h; 0 outside the measured range.
double along_vertical(const Photometry& p, size_t h, double v) {
    const auto& va = p.vertical_deg;
    if (v < va.front() || v > va.back()) return 0.0;
    if (va.size() == 1) return p.candela[p.index(h, 0)];
    size_t i;
    double t;
    locate(va, v, i, t);
    return (1 - t) * p.candela[p.index(h, i)] + t * p.candela[p.index(h, i + 1)];
}

// Interpolates between the first n stored planes around angle a (a within their range, or,
// with wrap, between plane n - 1 and the first plane + 360).
double across_planes(const Photometry& p, size_t n, double a, double v, bool wrap) {
    const auto& h = p.horizontal_deg;
    if (a > h[n - 1]) {
        if (!wrap) return 0.0;
        double t = (a - h[n - 1]) / (h.front() + 360 - h[n - 1]);
        return (1 - t) * along_vertical(p, n - 1, v) + t * along_vertical(p, 0, v);
    }
    if (a < h.front()) return 0.0;
    if (n == 1) return along_vertical(p, 0, v);
    size_t i;
    double t;
    locate(h, a, i, t);
    i = std::min(i, n - 2);
    t = (a - h[i]) / (h[i + 1] - h[i]);
    return (1 - t) * along_vertical(p, i, v) + t * along_vertical(p, i + 1, v);
}

// Band edges: midpoints between neighbouring angles, the outer edges at the first and last angle.
std::vector<double> band_edges(const std::vector<double>& a) {
    std::vector<double> edges(a.size() + 1);
    edges.front() = a.front();
    edges.back() = a.back();
    for (size_t i = 1; i < a.size(); ++i) edges[i] = 0.5 * (a[i - 1] + a[i]);
    return edges;
}

}  // namespace

double Photometry::intensity(double horizontal, double vertical) const {
    check_grid(*this);
    if (!std::isfinite(horizontal) || !std::isfinite(vertical)) return 0.0;
    const auto& h = horizontal_deg;
    // Folding the direction into the stored part gives the same value as interpolating on the
    // unfolded grid: mirror images of grid planes are grid planes.
    if (type == PhotometricType::C) {
        // Gamma -g in plane C is gamma g in plane C + 180.
        double g = wrap_360(vertical), c = horizontal;
        if (g > 180) {
            g = 360 - g;
            c += 180;
        }
        if (h.size() == 1) return along_vertical(*this, 0, g);
        c = wrap_360(c);
        switch (c_symmetry(h)) {
            case CSymmetry::quadrant:
                if (c > 180) c = 360 - c;
                if (c > 90) c = 180 - c;
                break;
            case CSymmetry::bilateral_0_180:
                if (c > 180) c = 360 - c;
                break;
            case CSymmetry::bilateral_90_270:
                if (c < 90 || c > 270) c = wrap_360(180 - c);
                break;
            case CSymmetry::none:
                c = h.front() + wrap_360(c - h.front());
                return across_planes(*this, open_planes(h), c, g, true);
        }
        return across_planes(*this, h.size(), c, g, false);
    }
    // Types A and B: latitude H (-90..90) toward the polar axis, plane angle V around it.
    double hh = wrap_360(horizontal + 180) - 180, vv = vertical;
    if (hh > 90) {
        hh = 180 - hh;
        vv += 180;
    } else if (hh < -90) {
        hh = -180 - hh;
        vv += 180;
    }
    vv = wrap_360(vv + 180) - 180;
    if (h.size() == 1) return along_vertical(*this, 0, vv);
    if (h.front() == 0) hh = std::fabs(hh);  // stored 0..90: laterally symmetric
    return across_planes(*this, h.size(), hh, vv, false);
}

double Photometry::total_flux() const {
    check_grid(*this);
    // Each stored value stands for a cell of the unfolded grid; its weight is that cell's solid
    // angle. The cell spans, in each direction, from the midpoint toward the previous angle to the
    // midpoint toward the next (clamped at the ends of the measured range). For the polar angle
    // (gamma for C, the latitude H for A and B) the solid angle of such a band is exact:
    // dphi * (cos a - cos b) for gamma, dV * (sin b - sin a) for latitude.
    std::vector<double> v_weight(vertical_deg.size()), h_weight(horizontal_deg.size(), 0.0);
    auto v_edges = band_edges(vertical_deg);
    if (type == PhotometricType::C) {
        for (size_t j = 0; j < vertical_deg.size(); ++j)
            v_weight[j] = std::cos(v_edges[j] * deg) - std::cos(v_edges[j + 1] * deg);
        if (horizontal_deg.size() == 1) {
            h_weight[0] = 2 * pi;
        } else {
            auto planes = unfold_type_c(horizontal_deg);
            // The closing plane (a0 + 360) is the first one again: trapezoid weights around the
            // circle.
            for (size_t k = 0; k < planes.size(); ++k) {
                double lo =
                    k == 0 ? planes[k].angle : 0.5 * (planes[k - 1].angle + planes[k].angle);
                double hi = k + 1 == planes.size() ? planes[k].angle
                                                   : 0.5 * (planes[k].angle + planes[k + 1].angle);
                h_weight[planes[k].index] += (hi - lo) * deg;
            }
        }
    } else {
        for (size_t j = 0; j < vertical_deg.size(); ++j)
            v_weight[j] = (v_edges[j + 1] - v_edges[j]) * deg;
        if (horizontal_deg.size() == 1) {
            h_weight[0] = 2.0;  // constant over latitude -90..90: integral of cos H
        } else {
            auto planes = unfold_type_ab(horizontal_deg);
            std::vector<double> angles(planes.size());
            for (size_t k = 0; k < planes.size(); ++k) angles[k] = planes[k].angle;
            auto h_edges = band_edges(angles);
            for (size_t k = 0; k < planes.size(); ++k)
                h_weight[planes[k].index] +=
                    std::sin(h_edges[k + 1] * deg) - std::sin(h_edges[k] * deg);
        }
    }
    double flux = 0;
    for (size_t h = 0; h < horizontal_deg.size(); ++h) {
        double plane = 0;
        for (size_t v = 0; v < vertical_deg.size(); ++v)
            plane += candela[index(h, v)] * v_weight[v];
        flux += plane * h_weight[h];
    }
    return flux;
}

double Photometry::max_candela() const {
    double m = 0;
    for (double c : candela) m = std::max(m, c);
    return m;
}

PhotometryFormat detect_photometry_format(const std::string& path) {
    const auto head = read_head(path, 1 << 16);
    const std::string utf8 =
        text_head_as_utf8({reinterpret_cast<const char*>(head.data()), head.size()});
    const std::string_view text = utf8;
    // IES: a version line. EULUMDAT: numbers on lines 2-7 (checked before looking for a TILT=
    // line, since EULUMDAT text lines may contain anything). IES LM-63-1986: a TILT= line.
    size_t start = text.find_first_not_of(" \t\r\n");
    if (start != std::string_view::npos &&
        (text.substr(start, 5) == "IESNA" || text.substr(start, 4) == "IES:"))
        return PhotometryFormat::ies;
    if (looks_like_eulumdat(text)) return PhotometryFormat::eulumdat;
    size_t pos = 0;
    while (pos < text.size()) {
        size_t end = text.find('\n', pos);
        std::string_view line =
            text.substr(pos, end == std::string_view::npos ? text.size() - pos : end - pos);
        size_t s = line.find_first_not_of(" \t");
        if (s != std::string_view::npos && line.substr(s, 5) == "TILT=")
            return PhotometryFormat::ies;
        if (end == std::string_view::npos) break;
        pos = end + 1;
    }
    fail(path,
         "neither an IES LM-63 file (no version line such as IESNA:LM-63-2002 and no TILT= line) "
         "nor an "
         "EULUMDAT file (lines 2 to 7 are not Ityp 0..3, Isym 0..4, Mc, Dc, Ng, Dg)");
}

Photometry read_photometry(const std::string& path) {
    if (detect_photometry_format(path) == PhotometryFormat::ies)
        return ies_to_photometry(read_ies(path));
    return eulumdat_to_photometry(read_eulumdat(path));
}

void write_photometry(const std::string& path, const Photometry& photometry,
                      PhotometryFormat format) {
    if (format == PhotometryFormat::ies) {
        write_ies(path, ies_from_photometry(photometry, path));
    } else {
        write_eulumdat(path, eulumdat_from_photometry(photometry, path));
    }
}

}  // namespace rayset
