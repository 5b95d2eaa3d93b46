// The complex light-source model of the paper (docs/light-model.md): what a build produces,
// what a .vdb model file holds, and what the emitter interface queries. Plain data; the
// algorithms live in model_build.cpp (build), model_file.cpp (store) and complex_source.cpp
// (query).
//
// Units: lengths mm, flux in `flux_unit` (W, or lm for files that carry only luminous flux),
// intensity flux/sr, radiance flux/(mm^2 sr).
#pragma once

#include "lightmodel/goniometric_diagram.h"
#include "lightmodel/lattice.h"
#include "lightmodel/sphere.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace rayset::lightmodel {

inline constexpr int kModelVersion = 2;

// How the goniometric diagrams are made: kernel estimates whose widths and grid follow the rays
// (diagram_estimate.h), or each intensity cell's histogram.
enum class DiagramSmoothing { none = 0, automatic = 1 };
// "auto" or "none", as raymodel build and rayset.Model.build take them.
inline const char* diagram_smoothing_name(DiagramSmoothing s) {
    return s == DiagramSmoothing::automatic ? "auto" : "none";
}

// Every number of the paper is an option with its value as the default.
struct ModelOptions {
    int density_resolution = 0;        // 0: adapted to the ray count (adapted_resolution)
    int max_density_resolution = 128;  // the paper's 128^3
    int flux_resolution = 32;          // the paper's 32^3
    int intensity_resolution = 5;      // the paper's 5^3
    int max_spheres_per_cell = 16;     // the paper's 16
    int samples_per_cell = 64;         // origins kept per boundary cell for the sphere fit
    // Goniometric diagrams: bands of cos(theta) and sectors of phi (goniometric_diagram.h), 0
    // for the grid the estimate chooses from the rays or the histogram's 40 x 12.
    DiagramSmoothing diagram_smoothing = DiagramSmoothing::automatic;
    int diagram_bands = 0;
    int diagram_sectors = 0;
    double spectral_bin_nm = 10;  // width of the per-cell spectrum bins, 380..780 nm
    int coverage_lines = 512;     // lines per flux cell measuring its visible fraction
    int threads = 0;              // 0: all cores
    uint64_t seed = 1;            // reservoir sampling of origins
    bool progress = false;        // progress bar on stderr
};

// The options that decide what a build makes, each by its one name: model files record them
// (build_options), raymodel build takes them as --NAME (dashes for underscores) and
// rayset.Model.build as keywords. visit(name, member, help) for each, in one order.
// spectral_bin_nm (a file records the bins themselves), threads and progress are not among them.
template <class Options, class Visit>
void visit_model_options(Options& o, Visit&& visit) {
    visit("density_resolution", o.density_resolution,
          "Cells along the longest axis of the density lattice; 0 adapts it to the ray count "
          "(round(sqrt(rays / 64)), at most max_density_resolution)");
    visit("max_density_resolution", o.max_density_resolution,
          "Upper bound of the adapted density resolution");
    visit("flux_resolution", o.flux_resolution, "Cells along the longest axis of the flux lattice");
    visit("intensity_resolution", o.intensity_resolution,
          "Cells along the longest axis of the intensity lattice (one goniometric diagram each)");
    visit("max_spheres_per_cell", o.max_spheres_per_cell,
          "Most spheres in one boundary cell (the paper's 16); fewer make the body cheaper for "
          "rays to enter, so light sampling of the model faster, at a coarser silhouette");
    visit("samples_per_cell", o.samples_per_cell,
          "Origins kept per boundary cell for the sphere fit");
    visit("coverage_lines", o.coverage_lines,
          "Lines per flux cell measuring the fraction of it that is seen from outside");
    visit("diagram_smoothing", o.diagram_smoothing,
          "Goniometric diagrams: 'auto' estimates each intensity cell's density of directions "
          "with kernels whose width (per direction, from all rays) and grid follow the rays; "
          "'none' keeps each cell's histogram (40 x 12 cells unless set below)");
    visit("diagram_bands", o.diagram_bands,
          "Bands of cos(theta) of each goniometric diagram (even); 0: chosen from the rays");
    visit("diagram_sectors", o.diagram_sectors,
          "Sectors of phi of each goniometric diagram; 0: chosen from the rays");
    visit("seed", o.seed, "Seed of the reservoir sampling of origins");
}

// Wavelength bins of the per-cell spectra: [first + i*width, first + (i+1)*width).
struct SpectralBins {
    double first_nm = 380, width_nm = 10;
    int count = 40;
    int bin_of(double wavelength_nm) const;  // clamped to the range; -1 for NaN
    // How many bins of `width_nm` cover the 400 nm from 380 to 780 (at least one), as a build
    // makes them; 0 for a width that is not positive and finite or too small for an int count.
    static int count_covering(double width_nm) {
        if (!(width_nm > 0) || !std::isfinite(width_nm)) return 0;
        const double count = std::max(1.0, std::round(400 / width_nm));
        return count <= std::numeric_limits<int>::max() ? int(count) : 0;
    }
    double centre(int bin) const { return first_nm + (bin + 0.5) * width_nm; }
};

// A cell of the flux lattice that holds light: where it is, what it emits, and which density
// voxels of the body it spreads that over (uniformly: the emission density is flux / volume).
struct FluxCell {
    Coord coord{};
    double flux = 0;              // flux_unit
    double luminous = 0;          // lm (NaN when the file gives no way to know it)
    int32_t intensity_cell = -1;  // index into LightModel::diagrams
    uint32_t first_voxel = 0;     // range into LightModel::voxels
    uint32_t voxel_count = 0;
    // Fraction of the cell's emission (points of its voxels, directions of its diagram) whose
    // line meets the body; radiance is divided by it so that the light a camera can see of the
    // cell is all of its light (docs/light-model.md, "Coverage").
    double visible_fraction = 1;
};

struct ModelSource {
    std::string path;  // ray file the model was built from
    std::string format;
    uint64_t rays = 0;
    double radiant = 0, luminous = 0;  // totals of the rays as read (W, lm; NaN if unknown)
    std::string unit = "mm";           // length unit of the file (the model is always in mm)
};

struct LightModel {
    ModelSource source;
    ModelOptions options;
    std::string flux_unit = "W";

    LatticeFrame density_frame, flux_frame, intensity_frame;
    // Occupied density voxels, grouped by flux cell (FluxCell::first_voxel/voxel_count).
    std::vector<Coord> voxels;
    std::vector<float> voxel_density;  // ray count of each voxel (for viewing)
    std::vector<Coord> boundary_voxels;
    std::vector<FluxCell> flux_cells;
    SpectralBins bins;
    std::vector<float> spectra;        // flux_cells.size() x bins.count, fractions summing to 1
                                       // (all zero when wavelengths are unknown)
    std::vector<Coord> diagram_cells;  // intensity-lattice coordinate of each diagram
    std::vector<GoniometricDiagram> diagrams;
    std::vector<Sphere> spheres;

    double total_flux() const;
    double total_luminous() const;
    Box bounds() const;  // of the body (spheres), mm
};

}  // namespace rayset::lightmodel
