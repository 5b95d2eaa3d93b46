// rayset's public API: the light-source model of a ray file (Zhdanov et al.; docs/light-model.md)
// built, read and written as one OpenVDB file, and the emitter interface a renderer queries it
// through. Link rayset::lightmodel. docs/api.md has the whole public API and examples.
//
// Units: lengths mm (the model is in mm whatever the ray file's unit), flux in the model's
// flux_unit (W, or lm for ray files that carry only luminous flux; SpectralSelect::luminous asks
// for lm), intensity flux/sr, radiance flux/(mm^2 sr), densities sr^-1 and mm^-3. Errors:
// rayset::Error (rays.h), naming the file and what is wrong.
#pragma once

#include "core/geometry.h"
#include "core/random.h"
#include "lightmodel/complex_source.h"
#include "lightmodel/emitter.h"
#include "lightmodel/model.h"
#include "lightmodel/model_build.h"
#include "lightmodel/model_file.h"

#include <rayset/rays.h>

namespace rayset {

// ---- Basic types (core/) ------------------------------------------------------------------------

// struct Vec3 { double x, y, z; }
//   Points (mm) and directions; +, -, scalar *, dot, cross, length, normalized.
// struct Rgb { double red, green, blue; }
//   Linear sRGB (BT.709 primaries, D65 white) radiometric channels; the luminous value of a
//   triple is 683 lm/W x (0.2126 red + 0.7152 green + 0.0722 blue).
// class Pcg32
//   A seedable generator whose numbers are the same on every platform: Pcg32(seed, stream = 0),
//   uniform() in [0, 1) (53 bits), uniform_float(), below(bound), next_u32(). Gives the uniform
//   numbers the emitter's sampling functions take.

// ---- The model (lightmodel/model.h, model_build.h, model_file.h) --------------------------------

// LightModel build_model(const std::string& ray_file, const ModelOptions& options,
//                        const BuildProgress& progress = {});
//   Builds the model of a ray file of any format (rays.h) in streaming passes, memory bounded by
//   the lattices: density lattice, flux lattice with per-cell spectra, goniometric diagrams,
//   the body of spheres. progress(pass, fraction) is called with the pass (1..4) and the
//   fraction done. Throws Error for a ray file it cannot read (as open_rays does) or rays
//   that carry no flux.
// using BuildProgress = std::function<void(int pass, double fraction)>
//
// struct ModelOptions
//   Every number of the paper, its value the default (what `raymodel build` takes):
//   density_resolution (0: adapted to the ray count, at most max_density_resolution 128),
//   flux_resolution 32, intensity_resolution 5, max_spheres_per_cell 16, samples_per_cell 64,
//   diagram_smoothing DiagramSmoothing::automatic (kernel estimates; none: histograms),
//   coverage_lines 512, diagram_bands and diagram_sectors (0: chosen from the rays),
//   spectral_bin_nm 10, threads 0 (all cores), seed 1, progress false (a progress bar on
//   stderr). visit_model_options(options, visit) calls visit(name, member, help) for each
//   option a build records, by the name raymodel build and rayset.Model.build give it.
//
// LightModel read_model(const std::string& path);
//   Reads a model file (.vdb). Throws Error naming the file and what is missing or
//   inconsistent.
// void write_model(const LightModel& model, const std::string& path);
//   Writes one .vdb file (OpenVDB's vdb_print lists it) through a temporary file renamed into
//   place, so that a failed write leaves nothing. Throws Error when it cannot be written.
//
// struct LightModel
//   The model as plain data: source (ModelSource: the ray file's path, format, rays, radiant W,
//   luminous lm, unit), options (the ModelOptions it was built with), flux_unit ("W" or
//   "lm"), the lattices, flux_cells, spectra, diagrams and spheres (the body: x, y, z, r in mm).
//   total_flux()      flux_unit
//   total_luminous()  lm (NaN when the rays give no way to know it)
//   bounds()          Box of the body, mm
// struct Box { Vec3 lower, upper; }

// ---- The emitter interface (lightmodel/emitter.h, complex_source.h) -----------------------------

// class Emitter
//   What a renderer asks of a light source built from rays (after pbrt-v4's Light). Every
//   quantity is in the selection's unit: SpectralSelect{quantity, band}, quantity
//   SpectralSelect::flux (flux_unit, the default) or SpectralSelect::luminous (lm), band >= 0
//   one spectral bin of the model only.
//   phi(select = {})             total flux
//   phi_colour()                 the whole flux as an Rgb
//   phi_spectrum()               the whole light as a BinnedSpectrum, where a spectral
//                                renderer's wavelengths are worth sampling
//   bounds()                     Box of the body, mm
//   intersect(origin, dir, tmax, hit)
//                                whether the ray origin + t dir, t in [0, tmax], enters the
//                                body; fills EmitterHit{t, point, normal} with the first entry
//   L(origin, dir, hit, select = {})
//                                radiance arriving at origin from dir, whose ray met the body
//                                at hit
//   L_colour(origin, dir, hit)   the same radiance as an Rgb
//   L_spectral(origin, dir, hit, query)
//                                the same radiance at query.nm[0..3] (nm), added to
//                                query.value[0..3]: per nm, scaled so that its integral against
//                                V(lambda) is the colour's luminance (SpectralQuery)
//   sample_Li(ref, u_cell, u_voxel, u_point, select = {}, spectral = nullptr)
//                                light sampling from the point ref with five uniform numbers
//                                in [0, 1): std::optional<LiSample>{wi (unit, toward the
//                                source), distance (to the body along wi, for the shadow ray),
//                                Li (radiance), pdf (sr^-1), Li_colour}; empty when nothing
//                                can be sampled from ref (ref inside the source)
//   pdf_Li(ref, wi)              the solid-angle density of sample_Li drawing wi from ref
//   sample_Le(u[7], select = {}) photon emission from seven uniform numbers in [0, 1):
//                                LeSample{origin, direction, flux (already divided by the
//                                densities), pdf_position (mm^-3), pdf_direction (sr^-1),
//                                cell, flux_colour, spectrum}; the mean flux of many photons
//                                is phi()
//   pdf_Le(origin, direction, pdf_position, pdf_direction)
//                                the densities of sample_Le emitting from origin along
//                                direction
//
// class ComplexSource : public Emitter
//   The paper's model behind the emitter interface: the body of spheres for what rays hit
//   (Embree), the emission volume for what they see and for light sampling, the goniometric
//   diagrams for photon directions.
//   ComplexSource(std::shared_ptr<const LightModel> model)
//                                builds the body's Embree scene; the model is shared, not copied
//   intensity(w, select = {})    far-field intensity toward the unit direction w, flux/sr
//   model()                      the LightModel
//   Its const functions may be called from any number of threads at once.
//
// struct SpectralSelect { Quantity quantity = flux; int band = -1; bool whole_flux() const; }
// struct SpectralQuery { double nm[4]; double value[4]; }
// class BinnedSpectrum
//   A spectrum over 360-830 nm in 10 nm bins: operator()(nm), sample(u) (a wavelength with
//   density proportional to the value), pdf(nm) (nm^-1), integral(), is_zero().
// struct EmitterHit, struct LiSample, struct LeSample (above)

using lightmodel::BinnedSpectrum;
using lightmodel::Box;
using lightmodel::build_model;
using lightmodel::BuildProgress;
using lightmodel::ComplexSource;
using lightmodel::DiagramSmoothing;
using lightmodel::Emitter;
using lightmodel::EmitterHit;
using lightmodel::LeSample;
using lightmodel::LightModel;
using lightmodel::LiSample;
using lightmodel::ModelOptions;
using lightmodel::ModelSource;
using lightmodel::read_model;
using lightmodel::SpectralQuery;
using lightmodel::SpectralSelect;
using lightmodel::visit_model_options;
using lightmodel::write_model;

}  // namespace rayset
