// Light sources whose emission is known exactly, for synthesising ray files and as the ground
// truth of the far-field, light-model and tracer tests. docs/synthetic-sources.md gives every
// formula with its reference.
//
// Units, everywhere: lengths mm, flux W, radiant intensity W/sr, radiance W/(mm^2 sr),
// irradiance W/mm^2 (x 1e6 for W/m^2), wavelength nm. Directions are unit vectors. All sources
// except the sphere sit in the plane z = 0 and emit toward +z.
#pragma once

#include "converters/analytic/analytic_geometry.h"
#include "converters/rays/ray.h"
#include "core/random.h"

#include <memory>
#include <string>
#include <vector>

namespace rayset::analytic {

// What a source emits spectrally: one wavelength, or a relative spectral power table (which
// then replaces the wavelength). Rays of a source carry radiant flux in W either way.
struct Spectrum {
    double wavelength_nm = 555;
    SpectralTable table;
    std::string table_file;  // where the table was read from, for parameters()
    bool has_table() const { return !table.wavelength.empty(); }
};

class Source {
public:
    virtual ~Source() = default;

    virtual std::string name() const = 0;
    // Every parameter as key=value text that make_source() reads back to the same source.
    virtual std::string parameters() const = 0;

    virtual double total_flux() const = 0;  // W
    // Luminous flux (lm) of the same light, from CIE V(lambda) and the source's spectrum.
    virtual double luminous_flux() const;
    // Far-field radiant intensity toward `direction` (W/sr): the source seen from infinitely far
    // away, so its size does not matter, only the projected emission.
    virtual double intensity(Vec3 direction) const = 0;
    // Radiance (W/(mm^2 sr)) leaving `point` toward `direction`: 0 off the emitter or toward a
    // side it does not emit into. Points within 1e-6 of the source's size of its surface count
    // as on it, so float ray origins do. NaN for the point emitter, whose radiance is a delta
    // function.
    virtual double radiance(Vec3 point, Vec3 direction) const = 0;
    // Irradiance (W/mm^2) at `point` on a receiver whose unit `normal` faces the light it
    // collects, exact at any distance and orientation (see each class for how).
    virtual double irradiance(Vec3 point, Vec3 normal) const = 0;
    // A ray with origin and direction drawn with density proportional to the emitted flux, and
    // its wavelength set when the source's rays differ in wavelength. Fluxes are left unknown:
    // synthesize() gives every ray the same share of the total.
    virtual Ray sample_ray(Pcg32& rng) const = 0;

    // Spectral description of the rays (kind, single wavelength, tables) into `header`.
    virtual void describe_spectrum(RayHeader& header) const;

protected:
    explicit Source(Spectrum spectrum) : spectrum_(std::move(spectrum)) {}
    std::string spectrum_parameters() const;
    Spectrum spectrum_;
};

// Uniform Lambertian disk of `radius` centred at the origin, emitting toward +z, or with its
// normal turned by `tilt_deg` (-90..90) from +z toward +x: (sin tilt, 0, cos tilt). Tilted, its
// far field has no symmetry about the z axis: I = L pi r^2 max(0, dot(normal, direction)).
class LambertianDisk : public Source {
public:
    LambertianDisk(double radius, double radiance, Spectrum spectrum = {}, double tilt_deg = 0);
    static LambertianDisk with_flux(double radius, double flux, Spectrum spectrum = {},
                                    double tilt_deg = 0);
    std::string name() const override { return "disk"; }
    std::string parameters() const override;
    double total_flux() const override;
    double intensity(Vec3 direction) const override;
    double radiance(Vec3 point, Vec3 direction) const override;
    double irradiance(Vec3 point, Vec3 normal) const override;  // closed form
    Ray sample_ray(Pcg32& rng) const override;
    double radius() const { return radius_; }
    double radiance() const { return radiance_; }
    Vec3 normal() const { return normal_; }

private:
    // A vector of the disk's own frame (normal +z) in the source's, and back.
    Vec3 from_disk(Vec3 v) const;
    Vec3 to_disk(Vec3 v) const;

    double radius_, radiance_, tilt_deg_;
    Vec3 normal_;
};

// Uniform Lambertian rectangle size_x by size_y centred at the origin, emitting toward +z.
class LambertianRectangle : public Source {
public:
    LambertianRectangle(double size_x, double size_y, double radiance, Spectrum spectrum = {});
    static LambertianRectangle with_flux(double size_x, double size_y, double flux,
                                         Spectrum spectrum = {});
    std::string name() const override { return "rectangle"; }
    std::string parameters() const override;
    double total_flux() const override;
    double intensity(Vec3 direction) const override;
    double radiance(Vec3 point, Vec3 direction) const override;
    double irradiance(Vec3 point, Vec3 normal) const override;  // exact contour sum
    Ray sample_ray(Pcg32& rng) const override;
    double radiance() const { return radiance_; }

private:
    double size_x_, size_y_, radiance_;
};

// Uniform Lambertian sphere of `radius` centred at the origin, emitting outward.
class LambertianSphere : public Source {
public:
    LambertianSphere(double radius, double radiance, Spectrum spectrum = {});
    static LambertianSphere with_flux(double radius, double flux, Spectrum spectrum = {});
    std::string name() const override { return "sphere"; }
    std::string parameters() const override;
    double total_flux() const override;
    double intensity(Vec3 direction) const override;
    double radiance(Vec3 point, Vec3 direction) const override;
    // Outside: the sphere subtends the same directions as its limb disk, so this is the disk's
    // closed form for that disk. Inside: 0. On the surface: the limit, pi L (1 + cos)/2.
    double irradiance(Vec3 point, Vec3 normal) const override;
    Ray sample_ray(Pcg32& rng) const override;
    double radiance() const { return radiance_; }

private:
    double radius_, radiance_;
};

// Point emitter at the origin with I = I0 cos^n(theta) toward +z, theta from +z, nothing
// toward z < 0. Its near field is the inverse-square law of a point: E = I cos_r / d^2, exact
// at every distance d > 0. n = 1 is the far field of any Lambertian plane emitter.
class CosineLobe : public Source {
public:
    CosineLobe(double exponent, double peak_intensity, Spectrum spectrum = {});
    static CosineLobe with_flux(double exponent, double flux, Spectrum spectrum = {});
    std::string name() const override { return "lobe"; }
    std::string parameters() const override;
    double total_flux() const override;  // 2 pi I0 / (n + 1)
    double intensity(Vec3 direction) const override;
    double radiance(Vec3 point, Vec3 direction) const override;  // NaN: a point has none
    double irradiance(Vec3 point, Vec3 normal) const override;
    Ray sample_ray(Pcg32& rng) const override;
    double exponent() const { return exponent_; }
    double peak_intensity() const { return peak_; }

private:
    double exponent_, peak_;
};

// One square Lambertian chip of a cluster: centre in z = 0, side length, flux, wavelength.
struct Chip {
    double x = 0, y = 0;
    double side = 1;
    double flux = 0;  // W
    double wavelength_nm = 555;
};

// Square Lambertian chips (edges along x and y) in concentric rings in the plane z = 0, all
// emitting toward +z. Ring k (0-based) has its chips evenly spaced at radius k * pitch starting
// on +x, counter-clockwise; ring 0 (radius 0) holds one chip or none. The default is 39 chips,
// 1 + 6 + 12 + 20. Chips must not overlap.
class ChipCluster : public Source {
public:
    struct Layout {
        std::vector<int> rings{1, 6, 12, 20};
        double chip_side = 1;  // mm
        double pitch = 2;      // mm between ring radii
    };
    // Chip i gets fluxes[i % size] W and wavelengths[i % size] nm (chips numbered ring by ring);
    // a table in `shared` gives every chip that spectrum instead of a wavelength.
    ChipCluster(const Layout& layout, const std::vector<double>& fluxes,
                const std::vector<double>& wavelengths, Spectrum shared = {});
    std::string name() const override { return "cluster"; }
    std::string parameters() const override;
    double total_flux() const override { return total_; }
    double intensity(Vec3 direction) const override;
    double radiance(Vec3 point, Vec3 direction) const override;
    double irradiance(Vec3 point, Vec3 normal) const override;  // sum of the chips' exact sums
    Ray sample_ray(Pcg32& rng) const override;
    double luminous_flux() const override;
    void describe_spectrum(RayHeader& header) const override;
    const std::vector<Chip>& chips() const { return chips_; }

private:
    Layout layout_;
    std::vector<double> fluxes_, wavelengths_;  // as given, for parameters()
    std::vector<Chip> chips_;
    std::vector<double> cumulative_;  // running sum of chip fluxes, for drawing a chip
    double total_ = 0;
    bool single_wavelength_ = true;
};

}  // namespace rayset::analytic
