#include "lightmodel/model_build.h"

#include "converters/colour/spectrum.h"
#include "converters/rays/ray_stream.h"
#include "core/random.h"
#include "lightmodel/coverage.h"
#include "lightmodel/density_lattice.h"
#include "lightmodel/diagram_estimate.h"
#include "lightmodel/sphere_fit.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>

namespace rayset::lightmodel {

namespace {

// The selected flux of a ray: radiant when the file has it, else luminous.
struct RayFlux {
    bool radiant;
    double operator()(const Ray& r) const { return radiant ? r.radiant : r.luminous; }
};

// Per-table fractions of flux in each spectral bin, for files with spectral tables.
std::vector<std::vector<double>> table_bins(const RayHeader& header, const SpectralBins& bins) {
    std::vector<std::vector<double>> out;
    for (const SpectralTable& t : header.spectral_tables) {
        std::vector<double> f(size_t(bins.count), 0.0);
        double sum = 0;
        for (size_t i = 0; i < t.wavelength.size(); ++i) {
            f[size_t(bins.bin_of(t.wavelength[i]))] += t.weight[i];
            sum += t.weight[i];
        }
        if (sum > 0)
            for (double& v : f) v /= sum;
        out.push_back(std::move(f));
    }
    return out;
}

using Report = std::function<void(int pass, double fraction)>;

// Origins in millimetres.
Vec3 origin_mm(const Ray& r, double scale) {
    return {r.origin.x * scale, r.origin.y * scale, r.origin.z * scale};
}

// The lattices nest: a density voxel belongs to the flux cell holding its centre, a flux cell
// to the intensity cell holding its centre (the three resolutions need not divide each
// other). A ray's flux and its direction so land in the same cell's flux and diagram.
struct LatticeNesting {
    std::vector<int32_t> flux_cell, intensity_cell;  // of each density voxel, linear indices

    explicit LatticeNesting(const LightModel& model) {
        const LatticeFrame& voxels = model.density_frame;
        flux_cell.resize(size_t(voxels.cell_count()));
        intensity_cell.resize(flux_cell.size());
        for (int64_t v = 0; v < voxels.cell_count(); ++v) {
            const Coord cell = model.flux_frame.cell_of(voxels.cell_centre(voxels.coord(v)));
            const Coord intensity =
                model.intensity_frame.cell_of(model.flux_frame.cell_centre(cell));
            flux_cell[size_t(v)] = int32_t(model.flux_frame.linear(cell));
            intensity_cell[size_t(v)] = int32_t(model.intensity_frame.linear(intensity));
        }
    }
};

// Sums per flux cell (one thread's in pass 2, then their total).
struct CellSums {
    std::vector<double> flux, luminous, spectrum;  // spectrum: `bins` values per cell
    CellSums(size_t cells, int bins)
        : flux(cells, 0), luminous(cells, 0), spectrum(cells * size_t(bins), 0) {}
    void add(const CellSums& other) {
        for (size_t c = 0; c < flux.size(); ++c)
            flux[c] += other.flux[c], luminous[c] += other.luminous[c];
        for (size_t i = 0; i < spectrum.size(); ++i) spectrum[i] += other.spectrum[i];
    }
};

// Where a ray's flux goes among the model's spectral bins: its spectral table's fractions, the
// file's single wavelength, or its own.
class RaySpectrum {
public:
    RaySpectrum(const RayHeader& header, const SpectralBins& bins)
        : header_(header), bins_(bins), tables_(table_bins(header, bins)) {}

    void add(const Ray& r, double phi, double* spectrum) const {
        const int count = bins_.count;
        if (r.spectrum >= 0) {
            const auto& f = tables_[size_t(r.spectrum)];
            for (int b = 0; b < count; ++b) spectrum[b] += phi * f[size_t(b)];
            return;
        }
        if (header_.spectral == SpectralKind::shared_table && !tables_.empty()) {
            for (int b = 0; b < count; ++b) spectrum[b] += phi * tables_[0][size_t(b)];
            return;
        }
        const float wl = header_.spectral == SpectralKind::single_wavelength
                             ? header_.single_wavelength
                         : header_.spectral == SpectralKind::shared_table ? kUnknown
                                                                          : r.wavelength;
        if (const int b = bins_.bin_of(wl); b >= 0) spectrum[b] += phi;
    }

private:
    const RayHeader& header_;
    const SpectralBins& bins_;
    std::vector<std::vector<double>> tables_;
};

// The rays' directions per intensity cell, for its diagram: the smoothed estimate's or each
// cell's histogram.
class DiagramRays {
public:
    DiagramRays(const ModelOptions& options, size_t cells) : options_(options) {
        if (options.diagram_smoothing == DiagramSmoothing::automatic)
            estimate_.emplace(cells);
        else
            histograms_.resize(cells);
    }

    void add(size_t cell, Vec3 w, double flux) {
        if (estimate_) return estimate_->add(cell, w, flux);
        if (!histograms_[cell])
            histograms_[cell] = std::make_unique<GoniometricDiagram>(bands(), sectors());
        histograms_[cell]->accumulate(w, flux);
    }

    // The diagrams of the cells `wanted`, in that order.
    std::vector<GoniometricDiagram> diagrams(const std::vector<size_t>& wanted) {
        if (estimate_)
            return estimate_->diagrams(wanted, options_.diagram_bands, options_.diagram_sectors);
        std::vector<GoniometricDiagram> out;
        for (size_t cell : wanted) {
            if (!histograms_[cell])
                histograms_[cell] = std::make_unique<GoniometricDiagram>(bands(), sectors());
            histograms_[cell]->finalize();
            out.push_back(std::move(*histograms_[cell]));
        }
        return out;
    }

private:
    int bands() const {
        return options_.diagram_bands > 0 ? options_.diagram_bands
                                          : GoniometricDiagram::kDefaultBands;
    }
    int sectors() const {
        return options_.diagram_sectors > 0 ? options_.diagram_sectors
                                            : GoniometricDiagram::kDefaultSectors;
    }
    const ModelOptions& options_;
    std::optional<DiagramEstimate> estimate_;
    std::vector<std::unique_ptr<GoniometricDiagram>> histograms_;
};

// Pass 1: the origins' box (mm) and the source's description. Returns the file's millimetres
// per unit.
double read_bounds(const std::string& ray_file, LightModel& model, Box& bounds,
                   const Report& report) {
    auto reader = open_rays(ray_file);
    const RayHeader& header = reader->header();
    const double scale = millimetres_per(header.unit);
    model.source.path = ray_file;
    model.source.format = to_string(header.format);
    model.source.unit = to_string(header.unit);
    RayChunk chunk;
    while (reader->read(chunk)) {
        for (const Ray& r : chunk.rays) bounds.extend(origin_mm(r, scale));
        report(1, reader->progress());
    }
    model.source.rays = reader->totals().rays;
    model.source.radiant = header.has_radiant ? reader->totals().radiant : std::nan("");
    if (model.source.rays == 0)
        throw Error(ray_file + ": the file holds no rays to build a model from");
    return scale;
}

// Pass 2's outcome.
struct RayTotals {
    CellSums sums;
    bool luminous_known = false, spectral = false;
};

// Pass 2: the origins into the density lattice, flux and spectra into their flux cells,
// directions into their intensity cell's diagram.
RayTotals accumulate_rays(const std::string& ray_file, double scale, LightModel& model,
                          const LatticeNesting& nesting, DensityLattice& density,
                          DiagramRays& diagram_rays, const Report& report) {
    const LatticeFrame& voxels = model.density_frame;
    const size_t flux_cells = size_t(model.flux_frame.cell_count());
    const int bins = model.bins.count;
    tbb::enumerable_thread_specific<CellSums> thread_sums(
        [&] { return CellSums(flux_cells, bins); });
    auto reader = open_rays(ray_file);
    const RayHeader& header = reader->header();
    const PhotometricWeights photometric(header);
    const RayFlux flux_of{header.has_radiant};
    const RaySpectrum spectrum_of(header, model.bins);
    model.flux_unit = header.has_radiant ? "W" : "lm";
    RayTotals totals{CellSums(flux_cells, bins), photometric.luminous_known(),
                     header.spectral != SpectralKind::none};
    std::vector<int32_t> voxel_of_ray;
    std::vector<Vec3> origins;
    RayChunk chunk;
    while (reader->read(chunk)) {
        const size_t n = chunk.size();
        origins.resize(n);
        voxel_of_ray.resize(n);
        tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 4096),
                          [&](const tbb::blocked_range<size_t>& range) {
                              CellSums& sums = thread_sums.local();
                              for (size_t i = range.begin(); i != range.end(); ++i) {
                                  const Ray& r = chunk.rays[i];
                                  origins[i] = origin_mm(r, scale);
                                  const int64_t v = voxels.linear(voxels.cell_of(origins[i]));
                                  const size_t cell = size_t(nesting.flux_cell[size_t(v)]);
                                  const double phi = flux_of(r);
                                  sums.flux[cell] += phi;
                                  if (totals.luminous_known)
                                      sums.luminous[cell] += photometric.luminous(r);
                                  spectrum_of.add(r, phi, &sums.spectrum[cell * size_t(bins)]);
                                  voxel_of_ray[i] = int32_t(v);
                              }
                          });
        // Directions one thread at a time: a histogram per cell and thread would not fit.
        for (size_t i = 0; i < n; ++i) {
            const Ray& r = chunk.rays[i];
            diagram_rays.add(size_t(nesting.intensity_cell[size_t(voxel_of_ray[i])]),
                             {r.direction.x, r.direction.y, r.direction.z}, flux_of(r));
        }
        density.add(origins);
        report(2, reader->progress());
    }
    for (const CellSums& sums : thread_sums) totals.sums.add(sums);
    return totals;
}

// The occupied voxels of each flux cell, with their ray counts.
struct CellVoxels {
    std::vector<std::vector<Coord>> voxels;
    std::vector<std::vector<float>> counts;
};

CellVoxels voxels_by_cell(const DensityLattice& density, const LatticeNesting& nesting,
                          size_t flux_cells) {
    CellVoxels out;
    out.voxels.resize(flux_cells);
    out.counts.resize(flux_cells);
    const openvdb::FloatGrid::Ptr grid = density.grid();
    for (auto it = grid->cbeginValueOn(); it; ++it) {
        if (!(*it > 0)) continue;
        const Coord c{it.getCoord().x(), it.getCoord().y(), it.getCoord().z()};
        const size_t cell = size_t(nesting.flux_cell[size_t(density.frame().linear(c))]);
        out.voxels[cell].push_back(c);
        out.counts[cell].push_back(*it);
    }
    return out;
}

// The flux cells that hold light, their voxels and spectra, and the diagrams of their
// intensity cells, in the model.
void add_flux_cells(LightModel& model, const RayTotals& totals, const DensityLattice& density,
                    const LatticeNesting& nesting, DiagramRays& diagram_rays) {
    const size_t flux_cells = size_t(model.flux_frame.cell_count());
    const int bins = model.bins.count;
    const CellVoxels occupied = voxels_by_cell(density, nesting, flux_cells);
    std::vector<int32_t> diagram_index(size_t(model.intensity_frame.cell_count()), -1);
    std::vector<size_t> diagram_of;  // intensity cell of each diagram
    for (size_t fc = 0; fc < flux_cells; ++fc) {
        if (!(totals.sums.flux[fc] > 0) || occupied.voxels[fc].empty()) continue;
        FluxCell cell;
        cell.coord = model.flux_frame.coord(int64_t(fc));
        cell.flux = totals.sums.flux[fc];
        cell.luminous = totals.luminous_known ? totals.sums.luminous[fc] : std::nan("");
        const size_t k =
            size_t(nesting.intensity_cell[size_t(density.frame().linear(occupied.voxels[fc][0]))]);
        if (diagram_index[k] < 0) {
            diagram_index[k] = int32_t(diagram_of.size());
            diagram_of.push_back(k);
            model.diagram_cells.push_back(model.intensity_frame.coord(int64_t(k)));
        }
        cell.intensity_cell = diagram_index[k];
        cell.first_voxel = uint32_t(model.voxels.size());
        cell.voxel_count = uint32_t(occupied.voxels[fc].size());
        model.voxels.insert(model.voxels.end(), occupied.voxels[fc].begin(),
                            occupied.voxels[fc].end());
        model.voxel_density.insert(model.voxel_density.end(), occupied.counts[fc].begin(),
                                   occupied.counts[fc].end());
        const double* spectrum = &totals.sums.spectrum[fc * size_t(bins)];
        double spectrum_sum = 0;
        for (int b = 0; b < bins; ++b) spectrum_sum += spectrum[b];
        for (int b = 0; b < bins; ++b)
            model.spectra.push_back(
                totals.spectral && spectrum_sum > 0 ? float(spectrum[b] / spectrum_sum) : 0.f);
        model.flux_cells.push_back(cell);
    }
    model.diagrams = diagram_rays.diagrams(diagram_of);
}

// Pass 3's outcome: up to per_cell origins of each boundary voxel (a uniform sample of its
// rays), and how many rays it held.
struct BoundarySamples {
    size_t per_cell;
    std::vector<Vec3> samples;  // per_cell slots per boundary voxel
    std::vector<uint64_t> seen;
};

// Pass 3: a reservoir sample of the origins in each boundary voxel.
BoundarySamples sample_boundary_origins(const std::string& ray_file, double scale,
                                        const LightModel& model, const ModelOptions& options,
                                        const Report& report) {
    const LatticeFrame& voxels = model.density_frame;
    std::vector<int32_t> boundary_slot(size_t(voxels.cell_count()), -1);
    for (size_t b = 0; b < model.boundary_voxels.size(); ++b)
        boundary_slot[size_t(voxels.linear(model.boundary_voxels[b]))] = int32_t(b);
    BoundarySamples out;
    out.per_cell = size_t(std::max(1, options.samples_per_cell));
    out.samples.resize(model.boundary_voxels.size() * out.per_cell);
    out.seen.assign(model.boundary_voxels.size(), 0);
    Pcg32 rng(options.seed);
    auto reader = open_rays(ray_file);
    RayChunk chunk;
    while (reader->read(chunk)) {
        for (const Ray& r : chunk.rays) {
            const Vec3 p = origin_mm(r, scale);
            const int32_t slot = boundary_slot[size_t(voxels.linear(voxels.cell_of(p)))];
            if (slot < 0) continue;
            const uint64_t k = out.seen[size_t(slot)]++;
            if (k < out.per_cell) {
                out.samples[size_t(slot) * out.per_cell + k] = p;
            } else if (const uint64_t j = uint64_t(rng.uniform() * double(k + 1));
                       j < out.per_cell) {
                out.samples[size_t(slot) * out.per_cell + j] = p;
            }
        }
        report(3, reader->progress());
    }
    return out;
}

// The spheres of each boundary voxel, fitted to its sampled origins, as many as its share of
// the rays calls for.
void fit_boundary_spheres(LightModel& model, const BoundarySamples& boundary,
                          const ModelOptions& options) {
    const LatticeFrame& voxels = model.density_frame;
    std::vector<double> boundary_counts(boundary.seen.begin(), boundary.seen.end());
    const double reference = reference_count(boundary_counts);
    std::vector<std::vector<Sphere>> fitted(model.boundary_voxels.size());
    tbb::parallel_for(size_t(0), model.boundary_voxels.size(), [&](size_t b) {
        const size_t n = size_t(std::min<uint64_t>(boundary.seen[b], boundary.per_cell));
        if (n == 0) return;
        const auto first = boundary.samples.begin() + std::ptrdiff_t(b * boundary.per_cell);
        const std::vector<Vec3> cell_samples(first, first + std::ptrdiff_t(n));
        const int k =
            spheres_for_count(double(boundary.seen[b]), reference, options.max_spheres_per_cell);
        fitted[b] = fit_cell_spheres(voxels.cell_lower(model.boundary_voxels[b]),
                                     voxels.cell_size(), cell_samples, k);
    });
    for (const auto& s : fitted) model.spheres.insert(model.spheres.end(), s.begin(), s.end());
}

}  // namespace

LightModel build_model(const std::string& ray_file, const ModelOptions& options,
                       const BuildProgress& progress) {
    std::optional<tbb::global_control> threads;
    if (options.threads > 0)
        threads.emplace(tbb::global_control::max_allowed_parallelism, size_t(options.threads));
    const Report report = [&](int pass, double f) {
        if (progress) progress(pass, f);
    };

    LightModel model;
    model.options = options;
    model.bins.width_nm = options.spectral_bin_nm;
    model.bins.count = SpectralBins::count_covering(options.spectral_bin_nm);
    if (model.bins.count == 0)
        throw std::invalid_argument("spectral_bin_nm must be a positive width in nm");

    Box bounds;
    const double scale = read_bounds(ray_file, model, bounds, report);
    const int density_resolution =
        options.density_resolution > 0
            ? options.density_resolution
            : adapted_resolution(model.source.rays, options.max_density_resolution);
    model.density_frame = LatticeFrame(bounds, density_resolution);
    model.flux_frame = LatticeFrame(bounds, options.flux_resolution);
    model.intensity_frame = LatticeFrame(bounds, options.intensity_resolution);
    const LatticeNesting nesting(model);

    DensityLattice density(model.density_frame);
    DiagramRays diagram_rays(options, size_t(model.intensity_frame.cell_count()));
    const RayTotals totals =
        accumulate_rays(ray_file, scale, model, nesting, density, diagram_rays, report);
    // Luminous flux of the rays: their luminous column, or their radiant flux weighted by
    // V(lambda).
    model.source.luminous = std::nan("");
    if (totals.luminous_known) {
        model.source.luminous = 0;
        for (double l : totals.sums.luminous) model.source.luminous += l;
    }
    add_flux_cells(model, totals, density, nesting, diagram_rays);
    if (model.flux_cells.empty())
        throw Error(ray_file + ": the rays carry no flux to build a model from");

    model.boundary_voxels = density.boundary_cells();
    fit_boundary_spheres(model, sample_boundary_origins(ray_file, scale, model, options, report),
                         options);
    measure_visible_fractions(model, options.coverage_lines, options.seed);
    report(4, 1);
    return model;
}

}  // namespace rayset::lightmodel
