// rayset's public API: ray files of every format read, written and converted, in constant memory
// whatever their size. Link rayset::converters. docs/api.md has the whole public API and examples.
//
// Formats: IES TM-25-13, LightTools binary and text, Zemax binary (.DAT/.SDF) and text, SPEOS,
// and rayset's CSV (docs/formats/ says what each holds and what is kept). Units: lengths in the
// file's unit (RayHeader::unit; TM-25 is mm), radiant flux W, luminous flux lm, wavelength nm.
// Errors: every function here throws rayset::Error (a std::runtime_error) for an input it cannot
// use, its message naming the file and the byte offset or line ("LED.ray: byte 1234: ...").
#pragma once

#include "converters/rays/ray.h"
#include "converters/rays/ray_stream.h"
#include "core/error.h"

namespace rayset {

// ---- Errors -------------------------------------------------------------------------------------

// class Error : public std::runtime_error
//   What every function of the public API throws for a file or a request it cannot use; what()
//   is UTF-8 text ready to print, naming the file and where in it.

// ---- Rays and their header (converters/rays/ray.h) ----------------------------------------------

// struct Ray
//   One ray: origin (Vec3f, the header's unit), unit direction, radiant (W), luminous (lm),
//   wavelength (nm) and spectrum (index into RayHeader::spectral_tables, -1 none). A value the
//   file does not carry is NaN (kUnknown); fluxes a reader hands out are absolute.
// struct Vec3f { float x, y, z; }
// inline constexpr float kUnknown (quiet NaN)
//
// struct RayHeader
//   What the rays of a file mean: format, unit, ray_count, which flux columns they carry
//   (has_radiant, has_luminous), stated totals (stated_radiant W, stated_luminous lm; NaN when
//   the file states none), spectral kind and tables, extra per-ray columns (extras), and the
//   descriptive fields the formats define (text, creation date, description, placement, ...),
//   kept through conversions where the target format can hold them.
// enum class RayFormat { tm25, lighttools_binary, lighttools_text, zemax_binary, zemax_text,
//                        speos, csv }
// enum class LengthUnit { mm, cm, m, inch, ft, um, nm }
// enum class SpectralKind { none, single_wavelength, per_ray_wavelength, shared_table,
//                           per_ray_table }
// struct SpectralTable { std::vector<float> wavelength (nm, ascending), weight (relative); }
// enum class ExtraKind, struct ExtraColumn { ExtraKind kind; std::string label; }
//   Per-ray columns beyond the standard ones (TM-25 polarisation and tristimulus, others).
// const char* to_string(RayFormat), to_string(LengthUnit)
//   The format's name as ray_format_from_name() reads it ("tm25", "zemax-text", ...); the unit's
//   symbol ("mm", "in", ...).
// double millimetres_per(LengthUnit unit)
//
// struct RayChunk { std::vector<Ray> rays; std::vector<float> extra; uint64_t first_index; }
//   A run of consecutive rays, first_index being the file index of rays[0]; `extra` holds
//   header.extras.size() values per ray, row by row.
// struct RayColumns
//   The same run one array per field (ox, oy, oz, dx, dy, dz, radiant, luminous, wavelength,
//   spectrum, extra), as RayReader::read_in_parts hands it out; ray(i) gives one as a Ray.

// ---- Reading ------------------------------------------------------------------------------------

// std::unique_ptr<RayReader> open_rays(const std::string& path,
//                                      const RayReadOptions& options = {});
//   Opens a ray file of any format (detected from its content unless options.format names it)
//   and checks its header against the file's size. Relative formats (LightTools, Zemax, SPEOS)
//   are first read once to sum their rays, so that they can be scaled to the stated total.
//   Throws Error for a file of no known format, a header that is wrong or a file cut short.
//
// struct RayReadOptions
//   flux_policy          which total wins when the stated one and the rays' sum disagree:
//                        FluxPolicy::format_default (the stated one for relative formats, the
//                        rays for TM-25 and CSV), FluxPolicy::stated or FluxPolicy::rays
//   direction_tolerance  directions whose length differs from 1 by more are an error (1e-3)
//   normalise_directions accept such directions and normalise them instead (false)
//   chunk_size           rays per chunk handed out (4096)
//   format               std::optional<RayFormat>: skip detection
//
// class RayReader
//   The validating reader open_rays() returns: each ray is checked as it is read (finite origin
//   and direction, unit direction, fluxes not negative, wavelength positive, spectrum index in
//   range), and a bad one throws Error naming its byte offset or line. Read it once, one way,
//   from one thread.
//   header()          the header, stated totals replaced by what the rays will sum to
//   file_header()     the header as the file states it
//   read(chunk)       the next chunk of rays in file order, false after the last; decoding runs
//                     a few chunks ahead on threads of the reader's own
//   read_in_parts(visit, progress = {})
//                     every ray, for consumers to whom the order does not matter: up to 8
//                     consecutive parts of the file read at once on all cores, each chunk given
//                     to visit(part, columns) on the thread that read it (a part's chunks in
//                     order); the number of parts depends on the file alone, so sums merged in
//                     part order are the same on every machine
//   totals()          RayTotals of the rays read so far: radiant (W), luminous (lm), rays,
//                     zero_flux_rays
//   warnings()        one line each: a stated total the rays disagree with, zero-flux rays, ...
//   progress()        fraction of the file read, 0..1
//   path()
//
// RayFormat detect_ray_format(const std::string& path);
//   The format of a file from its content (the .ray extension is ambiguous). Throws Error when
//   no format fits.
// std::optional<RayFormat> ray_format_from_name(const std::string& name);
//   A format from a name a user types or an unambiguous extension: "tm25", ".TM25RAY",
//   "lighttools", "lighttools-text", "zemax", ".dat", ".sdf", "zemax-text", "speos", "csv".

// ---- Writing and converting ---------------------------------------------------------------------

// std::unique_ptr<RayEncoder> create_rays(const std::string& path, RayFormat format,
//                                         const RayHeader& header);
//   A writer of `format` for rays `header` describes (its unit, flux columns, spectral kind and
//   extras say what each ray carries). Throws Error when the format cannot hold such rays (a
//   flux column it can write, SPEOS a radiant flux and a wavelength, ...) or the file cannot be
//   created.
//
// class RayEncoder
//   write(chunk)  writes rays; throws Error for a ray the format cannot hold (SPEOS: a ray
//                 without a known wavelength, ...)
//   finish()      patches counts and totals into the header and renames the file into place;
//                 a writer destroyed before finish() leaves no file behind, and whatever was at
//                 the path is untouched
//   dropped()     the header's fields the format cannot hold, one name each (not written)
//
// void copy_rays(RayReader& in, RayEncoder& out,
//                const std::function<void(double)>& progress = {});
//   Streams every ray of `in` into `out` and finishes it: a conversion (`rayconv convert`) is
//   open_rays, create_rays with the reader's header(), copy_rays. progress(fraction) is called
//   after each chunk.

}  // namespace rayset
