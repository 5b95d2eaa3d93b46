// The source as an emitting volume: the occupied voxels of the density lattice, each emitting
// its flux cell's flux spread evenly over the cell's occupied volume, into the directions of
// its intensity cell's goniometric diagram. Everything the emitter interface computes comes
// from line integrals through this volume, which is what keeps direct visibility, light
// sampling and photon emission consistent with each other (docs/light-model.md):
//   radiance along a line   L(w)   = sum over voxels v crossed  eps_v(w) * length_v,
//                            eps_v(w) = Phi_c D_k(w) / (V_c g_c)  (flux/(sr mm^3))
//   light-sampling density  p(w)   = sum over voxels v crossed  P_c / V_c * (t1^3 - t0^3) / 3
// where c is the voxel's flux cell, k its intensity cell, V_c the occupied volume of c, g_c the
// part of its emission the body shows (FluxCell::visible_fraction) and P_c = Phi_c / Phi the
// probability of choosing c. This is the paper's eq. 6 with dS (n.v)
// replaced by the exact projected area of each voxel along v (volume / path length), which
// never vanishes, so no grazing cosine is ever divided by.
#pragma once

#include "core/alias_table.h"
#include "lightmodel/colour.h"
#include "lightmodel/emission_spectrum.h"
#include "lightmodel/model.h"

#include <vector>

namespace rayset::lightmodel {

// Which part of the emitted light a query is about.
struct SpectralSelect {
    enum Quantity { flux, luminous } quantity = flux;  // flux_unit, or lm (luminous flux)
    int band = -1;                                     // >= 0: only that spectral bin of flux

    bool whole_flux() const { return quantity == flux && band < 0; }
};

// What a traversal of a line gathers beside its radiance; each output given is written.
struct LineAlso {
    Rgb* colour = nullptr;              // the radiance as a linear-sRGB triple (colour.h)
    SpectralQuery* spectral = nullptr;  // its values at the query's wavelengths, added to
    // The solid-angle density at the line's origin of its direction under sample_point()
    // restricted to the segment (pdf_direction() for tmin 0 and tmax infinite).
    double* pdf = nullptr;
    // line_density() of the line: the whole line, whatever segment the radiance is over.
    double* line_density = nullptr;
};

struct VolumeSample {
    Vec3 point;
    uint32_t flux_cell = 0;
    uint32_t voxel = 0;     // index into LightModel::voxels
    double pdf_volume = 0;  // mm^-3
};

class EmissionVolume {
public:
    explicit EmissionVolume(const LightModel& model);

    const LightModel& model() const { return model_; }
    double total(const SpectralSelect& select) const;
    double total_flux() const { return total_flux_; }  // flux_unit
    // Flux of one cell in the selected quantity.
    double cell_flux(uint32_t cell, const SpectralSelect& select) const;

    // Radiance arriving at `origin` from direction `dir`: the light the voxels on the segment
    // origin + t dir, t in [tmin, tmax], emit toward -dir; with `also`, more of the same line
    // from the same traversal.
    double radiance_toward(Vec3 origin, Vec3 dir, double tmin, double tmax,
                           const SpectralSelect& select, const LineAlso& also = {}) const;
    // The estimate a point drawn by sample_point() in `cell` gives of that line's radiance over
    // its solid-angle density, seen from `distance` along `dir` (toward the point): the
    // emission there over the point's density per unit solid angle, eps_c(-dir) / (p_V(c)
    // distance^2). Its mean over the points of a line is radiance_toward / pdf of that line.
    // Times `scale`; with `colour` and `spectral`, the same as radiance_toward gives them
    // (colour overwritten, spectral values added to).
    double point_estimate(uint32_t cell, Vec3 dir, double distance, double scale,
                          const SpectralSelect& select, Rgb* colour = nullptr,
                          SpectralQuery* spectral = nullptr) const;
    // Colour of one unit of a cell's flux (colour.h), and the colour of the whole source.
    const Rgb& cell_colour(uint32_t cell) const { return cell_colour_[cell]; }
    Rgb total_colour() const;
    // Luminance-normalised spectrum of one cell (emission_spectrum.h), and the source's whole
    // light as a spectrum: the cells' spectra weighted by their luminance weights.
    const BinnedSpectrum& cell_spectrum(uint32_t cell) const { return cell_spectrum_[cell]; }
    BinnedSpectrum total_spectrum() const;
    // Solid-angle density at `origin` of the direction `dir` under sample_point().
    double pdf_direction(Vec3 origin, Vec3 dir) const;
    // Density of the photon lines (a point by sample_point(), a direction by its intensity
    // cell's diagram) along the whole line through `origin` for light leaving toward -dir: per
    // unit area across the line and per steradian, the line integral of point_density D_k.
    double line_density(Vec3 origin, Vec3 dir) const;

    // A point of the volume with density proportional to the emission (cell by flux, then
    // uniform in the cell's occupied voxels: the same distribution as rejection sampling of a
    // point in the cell against the occupied body, without the rejected draws).
    VolumeSample sample_point(double u_cell, double u_voxel, Vec3 u_point) const;
    // A point uniform in the occupied voxels of one cell.
    Vec3 sample_in_cell(uint32_t cell, double u_voxel, Vec3 u_point) const;
    // The occupied voxel of `cell` that sample_in_cell draws with `u_voxel`, and a point
    // uniform in one voxel.
    uint32_t voxel_in_cell(uint32_t cell, double u_voxel) const;
    Vec3 point_in_voxel(uint32_t voxel, Vec3 u_point) const;
    double pdf_point(Vec3 point) const;  // mm^-3, 0 outside the volume

    // The flux cell of the occupied voxel holding `point`, -1 if none.
    int32_t cell_at(Vec3 point) const;
    double cell_volume(uint32_t cell) const;  // occupied volume, mm^3
    // Density of sample_point() in the occupied voxels of `cell`, mm^-3.
    double point_density(uint32_t cell) const;

    // Visits the occupied voxels the segment crosses: f(flux_cell, t0, t1), in order.
    template <class F>
    void traverse(Vec3 origin, Vec3 dir, double tmin, double tmax, F&& f) const;

private:
    // What a line integral reads of a flux cell, together for the cache and free of divisions.
    struct LineTerms {
        double flux = 0;           // Phi_c
        double emission = 0;       // 1 / (V_c g_c): eps per unit flux and diagram density
        double point_density = 0;  // P_c / V_c
        int32_t diagram = -1;      // intensity cell k
    };

    // What `cell` emits per unit of its flux, `per_flux` (its diagram's density times a length
    // or a point's weight, over V_c g_c), in the selected quantity; its colour and spectral
    // values added to `colour` and `spectral` when given.
    double emission(uint32_t cell, double per_flux, const SpectralSelect& select, Rgb* colour,
                    SpectralQuery* spectral) const;
    // Solid-angle density, seen from a line's origin, that the voxels of `cell` between t0 and
    // t1 along it give its direction under sample_point(): the integral of point_density t^2.
    double direction_density(uint32_t cell, double t0, double t1) const;
    // What the voxels of `cell` between t0 and t1 along a line give its line_density, their
    // diagram's density along the line being `diagram_pdf`.
    double line_term(uint32_t cell, double diagram_pdf, double t0, double t1) const {
        return line_terms_[cell].point_density * diagram_pdf * (t1 - t0);
    }

    const LightModel& model_;
    std::vector<int32_t> voxel_cell_;    // dense density lattice -> flux cell, -1 empty
    std::vector<LineTerms> line_terms_;  // per flux cell
    AliasTable cells_;                   // flux cells, drawn by flux
    double total_flux_ = 0;
    std::vector<Rgb> cell_colour_;
    std::vector<BinnedSpectrum> cell_spectrum_;
    double voxel_volume_ = 0;
};

}  // namespace rayset::lightmodel

#include "lightmodel/emission_volume_traverse.h"
