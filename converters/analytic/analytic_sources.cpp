#include "converters/analytic/analytic_sources.h"

#include "converters/colour/spectrum.h"
#include "converters/rays/io.h"
#include "core/error.h"

#include <algorithm>
#include <cmath>

namespace rayset::analytic {

// Sampling uses only +, -, *, / and sqrt (rejection instead of trigonometry), which IEEE 754
// rounds exactly, so a seed gives the same rays bit for bit on every conforming platform. The
// cos^n lobe needs pow() for n != 1 and is the one exception.

namespace {

void require_positive(const char* source, const char* what, const char* unit, double value) {
    if (!(value > 0 && std::isfinite(value)))
        throw Error(std::string(source) + ": " + what + " must be a positive number of " + unit +
                    ", not " + format_double(value));
}

void check_spectrum(const char* source, const Spectrum& spectrum) {
    if (!spectrum.has_table()) require_positive(source, "wavelength", "nm", spectrum.wavelength_nm);
}

// Uniform point in the open unit disk (rejection from the square).
void unit_disk(Pcg32& rng, double& x, double& y) {
    do {
        x = 2 * rng.uniform() - 1;
        y = 2 * rng.uniform() - 1;
    } while (x * x + y * y >= 1);
}

// Cosine-weighted direction about +z (Malley's method: project a uniform disk point up).
Vec3 cosine_direction(Pcg32& rng) {
    double x, y;
    unit_disk(rng, x, y);
    return {x, y, std::sqrt(std::max(0.0, 1 - x * x - y * y))};
}

Vec3f to_float(Vec3 v) { return {float(v.x), float(v.y), float(v.z)}; }

Ray make_ray(Vec3 origin, Vec3 direction) {
    Ray ray;
    ray.origin = to_float(origin);
    ray.direction = to_float(direction);
    return ray;
}

double cos_z(Vec3 direction) { return direction.z / length(direction); }

bool within(double value, double tolerance) { return std::abs(value) <= tolerance; }

std::vector<Vec3> rectangle_corners(double cx, double cy, double sx, double sy) {
    const double hx = sx / 2, hy = sy / 2;
    return {
        {cx - hx, cy - hy, 0}, {cx + hx, cy - hy, 0}, {cx + hx, cy + hy, 0}, {cx - hx, cy + hy, 0}};
}

std::string join(const std::vector<double>& values) {
    std::string out;
    for (size_t i = 0; i < values.size(); ++i) out += (i ? "," : "") + format_double(values[i]);
    return out;
}

}  // namespace

// ---------------------------------------------------------------------------------------------

void Source::describe_spectrum(RayHeader& header) const {
    header.spectral_tables.clear();
    if (spectrum_.has_table()) {
        header.spectral = SpectralKind::shared_table;
        header.spectral_tables.push_back(spectrum_.table);
        header.single_wavelength = kUnknown;
        header.min_wavelength = spectrum_.table.wavelength.front();
        header.max_wavelength = spectrum_.table.wavelength.back();
    } else {
        header.spectral = SpectralKind::single_wavelength;
        header.single_wavelength = float(spectrum_.wavelength_nm);
        header.min_wavelength = header.max_wavelength = header.single_wavelength;
    }
}

double Source::luminous_flux() const {
    const double efficacy =
        spectrum_.has_table() ? luminous_efficacy(spectrum_.table)
                              : kMaxLuminousEfficacy * photopic_efficiency(spectrum_.wavelength_nm);
    return total_flux() * efficacy;
}

std::string Source::spectrum_parameters() const {
    if (spectrum_.has_table()) return "spectrum=" + spectrum_.table_file;
    return "wavelength=" + format_double(spectrum_.wavelength_nm);
}

// ---------------------------------------------------------------------------------------------

LambertianDisk::LambertianDisk(double radius, double radiance, Spectrum spectrum, double tilt_deg)
    : Source(std::move(spectrum)), radius_(radius), radiance_(radiance), tilt_deg_(tilt_deg) {
    require_positive("disk", "radius", "mm", radius);
    require_positive("disk", "radiance", "W/(mm^2 sr)", radiance);
    if (!(std::abs(tilt_deg) <= 90))
        throw Error("disk: tilt must be a number of degrees from -90 to 90, not " +
                    format_double(tilt_deg));
    check_spectrum("disk", spectrum_);
    normal_ = from_disk({0, 0, 1});
}

LambertianDisk LambertianDisk::with_flux(double radius, double flux, Spectrum spectrum,
                                         double tilt_deg) {
    require_positive("disk", "radius", "mm", radius);
    require_positive("disk", "flux", "W", flux);
    return LambertianDisk(radius, flux / (kPi * kPi * radius * radius), std::move(spectrum),
                          tilt_deg);
}

// A rotation about y; none at all without a tilt, so untilted disks give the rays they always gave.
Vec3 LambertianDisk::from_disk(Vec3 v) const {
    if (tilt_deg_ == 0) return v;
    const double c = std::cos(tilt_deg_ * kPi / 180), s = std::sin(tilt_deg_ * kPi / 180);
    return {c * v.x + s * v.z, v.y, -s * v.x + c * v.z};
}

Vec3 LambertianDisk::to_disk(Vec3 v) const {
    if (tilt_deg_ == 0) return v;
    const double c = std::cos(tilt_deg_ * kPi / 180), s = std::sin(tilt_deg_ * kPi / 180);
    return {c * v.x - s * v.z, v.y, s * v.x + c * v.z};
}

std::string LambertianDisk::parameters() const {
    return "radius=" + format_double(radius_) +
           (tilt_deg_ != 0 ? " tilt=" + format_double(tilt_deg_) : "") +
           " radiance=" + format_double(radiance_) + " " + spectrum_parameters();
}

double LambertianDisk::total_flux() const { return kPi * radiance_ * kPi * radius_ * radius_; }

double LambertianDisk::intensity(Vec3 direction) const {
    return radiance_ * kPi * radius_ * radius_ * std::max(0.0, cos_z(to_disk(direction)));
}

double LambertianDisk::radiance(Vec3 point, Vec3 direction) const {
    const double tolerance = 1e-6 * radius_;
    const Vec3 p = to_disk(point);
    const bool on = within(p.z, tolerance) && std::hypot(p.x, p.y) <= radius_ + tolerance;
    return on && to_disk(direction).z > 0 ? radiance_ : 0;
}

double LambertianDisk::irradiance(Vec3 point, Vec3 normal) const {
    return disk_irradiance(radiance_, {0, 0, 0}, normal_, radius_, point, normal);
}

Ray LambertianDisk::sample_ray(Pcg32& rng) const {
    double x, y;
    unit_disk(rng, x, y);
    return make_ray(from_disk({radius_ * x, radius_ * y, 0}), from_disk(cosine_direction(rng)));
}

// ---------------------------------------------------------------------------------------------

LambertianRectangle::LambertianRectangle(double size_x, double size_y, double radiance,
                                         Spectrum spectrum)
    : Source(std::move(spectrum)), size_x_(size_x), size_y_(size_y), radiance_(radiance) {
    require_positive("rectangle", "size_x", "mm", size_x);
    require_positive("rectangle", "size_y", "mm", size_y);
    require_positive("rectangle", "radiance", "W/(mm^2 sr)", radiance);
    check_spectrum("rectangle", spectrum_);
}

LambertianRectangle LambertianRectangle::with_flux(double size_x, double size_y, double flux,
                                                   Spectrum spectrum) {
    require_positive("rectangle", "size_x", "mm", size_x);
    require_positive("rectangle", "size_y", "mm", size_y);
    require_positive("rectangle", "flux", "W", flux);
    return LambertianRectangle(size_x, size_y, flux / (kPi * size_x * size_y), std::move(spectrum));
}

std::string LambertianRectangle::parameters() const {
    return "size_x=" + format_double(size_x_) + " size_y=" + format_double(size_y_) +
           " radiance=" + format_double(radiance_) + " " + spectrum_parameters();
}

double LambertianRectangle::total_flux() const { return kPi * radiance_ * size_x_ * size_y_; }

double LambertianRectangle::intensity(Vec3 direction) const {
    return radiance_ * size_x_ * size_y_ * std::max(0.0, cos_z(direction));
}

double LambertianRectangle::radiance(Vec3 point, Vec3 direction) const {
    const double tolerance = 1e-6 * std::max(size_x_, size_y_);
    const bool on = within(point.z, tolerance) && std::abs(point.x) <= size_x_ / 2 + tolerance &&
                    std::abs(point.y) <= size_y_ / 2 + tolerance;
    return on && direction.z > 0 ? radiance_ : 0;
}

double LambertianRectangle::irradiance(Vec3 point, Vec3 normal) const {
    return polygon_irradiance(radiance_, rectangle_corners(0, 0, size_x_, size_y_), point, normal);
}

Ray LambertianRectangle::sample_ray(Pcg32& rng) const {
    const double x = (rng.uniform() - 0.5) * size_x_;
    const double y = (rng.uniform() - 0.5) * size_y_;
    return make_ray({x, y, 0}, cosine_direction(rng));
}

// ---------------------------------------------------------------------------------------------

LambertianSphere::LambertianSphere(double radius, double radiance, Spectrum spectrum)
    : Source(std::move(spectrum)), radius_(radius), radiance_(radiance) {
    require_positive("sphere", "radius", "mm", radius);
    require_positive("sphere", "radiance", "W/(mm^2 sr)", radiance);
    check_spectrum("sphere", spectrum_);
}

LambertianSphere LambertianSphere::with_flux(double radius, double flux, Spectrum spectrum) {
    require_positive("sphere", "radius", "mm", radius);
    require_positive("sphere", "flux", "W", flux);
    return LambertianSphere(radius, flux / (4 * kPi * kPi * radius * radius), std::move(spectrum));
}

std::string LambertianSphere::parameters() const {
    return "radius=" + format_double(radius_) + " radiance=" + format_double(radiance_) + " " +
           spectrum_parameters();
}

double LambertianSphere::total_flux() const {
    return kPi * radiance_ * 4 * kPi * radius_ * radius_;
}

double LambertianSphere::intensity(Vec3) const { return radiance_ * kPi * radius_ * radius_; }

double LambertianSphere::radiance(Vec3 point, Vec3 direction) const {
    const double r = length(point);
    return within(r - radius_, 1e-6 * radius_) && dot(point, direction) > 0 ? radiance_ : 0;
}

double LambertianSphere::irradiance(Vec3 point, Vec3 normal) const {
    const double d = length(point);
    if (d < radius_) return 0;
    const Vec3 outward = (1 / d) * point;
    if (d == radius_) return kPi * radiance_ * (1 - dot(normal, outward)) / 2;
    // The limb circle: where the tangent cone from the point touches the sphere.
    const double ratio = radius_ / d;
    const Vec3 limb_centre = (radius_ * ratio) * outward;
    const double limb_radius = radius_ * std::sqrt((1 - ratio) * (1 + ratio));
    return disk_irradiance(radiance_, limb_centre, outward, limb_radius, point, normal);
}

Ray LambertianSphere::sample_ray(Pcg32& rng) const {
    double u, v;
    unit_disk(rng, u, v);  // Marsaglia (1972): a uniform point on the sphere from one on a disk
    const double s = u * u + v * v, root = 2 * std::sqrt(1 - s);
    const Vec3 normal{u * root, v * root, 1 - 2 * s};
    Vec3 e1, e2;
    orthonormal_basis(normal, e1, e2);
    const Vec3 local = cosine_direction(rng);
    const Vec3 direction = local.x * e1 + local.y * e2 + local.z * normal;
    return make_ray(radius_ * normal, direction);
}

// ---------------------------------------------------------------------------------------------

CosineLobe::CosineLobe(double exponent, double peak_intensity, Spectrum spectrum)
    : Source(std::move(spectrum)), exponent_(exponent), peak_(peak_intensity) {
    if (!(exponent >= 0 && std::isfinite(exponent)))
        throw Error("lobe: exponent n must be a number >= 0, not " + format_double(exponent));
    require_positive("lobe", "peak intensity", "W/sr", peak_intensity);
    check_spectrum("lobe", spectrum_);
}

CosineLobe CosineLobe::with_flux(double exponent, double flux, Spectrum spectrum) {
    require_positive("lobe", "flux", "W", flux);
    return CosineLobe(exponent, flux * (exponent + 1) / (2 * kPi), std::move(spectrum));
}

std::string CosineLobe::parameters() const {
    return "n=" + format_double(exponent_) + " intensity=" + format_double(peak_) + " " +
           spectrum_parameters();
}

double CosineLobe::total_flux() const { return 2 * kPi * peak_ / (exponent_ + 1); }

double CosineLobe::intensity(Vec3 direction) const {
    const double c = cos_z(direction);
    return c > 0 ? peak_ * std::pow(c, exponent_) : 0;
}

double CosineLobe::radiance(Vec3, Vec3) const { return std::nan(""); }

double CosineLobe::irradiance(Vec3 point, Vec3 normal) const {
    const double d = length(point);
    if (!(d > 0)) return std::nan("");
    const double receiver_cos = -dot(normal, point) / d;
    return receiver_cos > 0 ? intensity(point) * receiver_cos / (d * d) : 0;
}

Ray CosineLobe::sample_ray(Pcg32& rng) const {
    // cos(theta) = u^(1/(n+1)) inverts the cumulative flux 1 - cos^(n+1); the azimuth comes
    // from a disk point so that no sin/cos is needed.
    const double c = exponent_ == 1 ? std::sqrt(1 - rng.uniform())
                                    : std::pow(1 - rng.uniform(), 1 / (exponent_ + 1));
    const double s = std::sqrt(std::max(0.0, 1 - c * c));
    double x, y, r2;
    do unit_disk(rng, x, y), r2 = x * x + y * y;
    while (r2 == 0);
    const double scale = s / std::sqrt(r2);
    return make_ray({0, 0, 0}, {x * scale, y * scale, c});
}

// ---------------------------------------------------------------------------------------------

ChipCluster::ChipCluster(const Layout& layout, const std::vector<double>& fluxes,
                         const std::vector<double>& wavelengths, Spectrum shared)
    : Source(std::move(shared)), layout_(layout), fluxes_(fluxes), wavelengths_(wavelengths) {
    require_positive("cluster", "chip side", "mm", layout.chip_side);
    require_positive("cluster", "pitch", "mm", layout.pitch);
    if (layout.rings.empty()) throw Error("cluster: rings must list at least one ring");
    if (fluxes.empty()) throw Error("cluster: no chip flux given");
    for (double f : fluxes) require_positive("cluster", "chip flux", "W", f);
    if (!spectrum_.has_table()) {
        if (wavelengths.empty()) throw Error("cluster: no chip wavelength given");
        for (double w : wavelengths) require_positive("cluster", "chip wavelength", "nm", w);
    }
    for (size_t k = 0; k < layout.rings.size(); ++k) {
        const int count = layout.rings[k];
        const double radius = double(k) * layout.pitch;
        if (count < 0)
            throw Error("cluster: ring " + std::to_string(k + 1) + " cannot hold " +
                        std::to_string(count) + " chips");
        if (radius == 0 && count > 1)
            throw Error("cluster: ring 1 has radius 0, so it holds one chip or none, not " +
                        std::to_string(count));
        for (int j = 0; j < count; ++j) {
            const double angle = 2 * kPi * j / count;
            Chip chip;
            chip.x = radius == 0 ? 0 : radius * std::cos(angle);
            chip.y = radius == 0 ? 0 : radius * std::sin(angle);
            chip.side = layout.chip_side;
            const size_t i = chips_.size();
            chip.flux = fluxes[i % fluxes.size()];
            chip.wavelength_nm =
                wavelengths.empty() ? kUnknown : wavelengths[i % wavelengths.size()];
            chips_.push_back(chip);
        }
    }
    if (chips_.empty()) throw Error("cluster: the rings hold no chip");
    const double side = layout.chip_side;
    for (size_t i = 0; i < chips_.size(); ++i)
        for (size_t j = i + 1; j < chips_.size(); ++j)
            if (std::abs(chips_[i].x - chips_[j].x) < side &&
                std::abs(chips_[i].y - chips_[j].y) < side)
                throw Error("cluster: chips " + std::to_string(i + 1) + " and " +
                            std::to_string(j + 1) +
                            " overlap; use a larger pitch or a smaller chip");
    for (const Chip& c : chips_) {
        total_ += c.flux;
        cumulative_.push_back(total_);
        single_wavelength_ = single_wavelength_ && c.wavelength_nm == chips_[0].wavelength_nm;
    }
    spectrum_.wavelength_nm = chips_[0].wavelength_nm;
}

std::string ChipCluster::parameters() const {
    std::string rings;
    for (size_t k = 0; k < layout_.rings.size(); ++k)
        rings += (k ? "," : "") + std::to_string(layout_.rings[k]);
    std::string text = "rings=" + rings + " chip=" + format_double(layout_.chip_side) +
                       " pitch=" + format_double(layout_.pitch) + " chip_flux=" + join(fluxes_);
    return text + " " +
           (spectrum_.has_table() ? spectrum_parameters() : "wavelength=" + join(wavelengths_));
}

double ChipCluster::intensity(Vec3 direction) const {
    // Each chip gives L A cos = flux cos / pi about its own centre; in the far field the
    // offsets between chips do not matter.
    return total_ / kPi * std::max(0.0, cos_z(direction));
}

double ChipCluster::radiance(Vec3 point, Vec3 direction) const {
    const double half = layout_.chip_side / 2, tolerance = 1e-6 * layout_.chip_side;
    if (!within(point.z, tolerance) || !(direction.z > 0)) return 0;
    for (const Chip& c : chips_)
        if (std::abs(point.x - c.x) <= half + tolerance &&
            std::abs(point.y - c.y) <= half + tolerance)
            return c.flux / (kPi * c.side * c.side);
    return 0;
}

double ChipCluster::irradiance(Vec3 point, Vec3 normal) const {
    double sum = 0;
    for (const Chip& c : chips_)
        sum += polygon_irradiance(c.flux / (kPi * c.side * c.side),
                                  rectangle_corners(c.x, c.y, c.side, c.side), point, normal);
    return sum;
}

Ray ChipCluster::sample_ray(Pcg32& rng) const {
    const double target = rng.uniform() * total_;
    const size_t i = std::min<size_t>(
        std::upper_bound(cumulative_.begin(), cumulative_.end(), target) - cumulative_.begin(),
        chips_.size() - 1);
    const Chip& c = chips_[i];
    const double x = c.x + (rng.uniform() - 0.5) * c.side;
    const double y = c.y + (rng.uniform() - 0.5) * c.side;
    Ray ray = make_ray({x, y, 0}, cosine_direction(rng));
    if (!single_wavelength_ && !spectrum_.has_table()) ray.wavelength = float(c.wavelength_nm);
    return ray;
}

double ChipCluster::luminous_flux() const {
    if (spectrum_.has_table()) return Source::luminous_flux();
    double sum = 0;
    for (const Chip& c : chips_)
        sum += c.flux * kMaxLuminousEfficacy * photopic_efficiency(c.wavelength_nm);
    return sum;
}

void ChipCluster::describe_spectrum(RayHeader& header) const {
    if (spectrum_.has_table() || single_wavelength_) {
        Source::describe_spectrum(header);
        return;
    }
    header.spectral = SpectralKind::per_ray_wavelength;
    header.spectral_tables.clear();
    header.single_wavelength = kUnknown;
    auto [lo, hi] = std::minmax_element(
        chips_.begin(), chips_.end(),
        [](const Chip& a, const Chip& b) { return a.wavelength_nm < b.wavelength_nm; });
    header.min_wavelength = float(lo->wavelength_nm);
    header.max_wavelength = float(hi->wavelength_nm);
}

}  // namespace rayset::analytic
