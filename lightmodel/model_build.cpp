#include "lightmodel/model_build.h"

#include "converters/ray_stream.h"
#include "converters/spectrum.h"
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
#include <map>
#include <memory>
#include <optional>

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

// What every thread accumulates in pass 2, merged at the end.
struct Accumulator {
    std::vector<double> flux, luminous, spectrum;  // per flux cell (spectrum: x bins)
    std::vector<Vec3> points;                      // scratch: a chunk's origins in mm
};

// The rays' directions per intensity cell, for its diagram: the smoothed estimate's or each
// cell's histogram.
class DiagramRays {
public:
    DiagramRays(const ModelOptions& options, size_t cells) : options_(options) {
        if (options.smooth_diagrams)
            estimate_.emplace(cells);
        else
            histograms_.resize(cells);
    }

    void add(size_t cell, Vec3 w, double flux) {
        if (estimate_) return estimate_->add(cell, w, flux);
        if (!histograms_[cell]) histograms_[cell] = std::make_unique<GoniometricDiagram>(bands(), sectors());
        histograms_[cell]->accumulate(w, flux);
    }

    // The diagrams of the cells `wanted`, in that order.
    std::vector<GoniometricDiagram> diagrams(const std::vector<size_t>& wanted) {
        if (estimate_) return estimate_->diagrams(wanted, options_.diagram_bands, options_.diagram_sectors);
        std::vector<GoniometricDiagram> out;
        for (size_t cell : wanted) {
            if (!histograms_[cell]) histograms_[cell] = std::make_unique<GoniometricDiagram>(bands(), sectors());
            histograms_[cell]->finalize();
            out.push_back(std::move(*histograms_[cell]));
        }
        return out;
    }

private:
    int bands() const { return options_.diagram_bands > 0 ? options_.diagram_bands : GoniometricDiagram::kDefaultBands; }
    int sectors() const {
        return options_.diagram_sectors > 0 ? options_.diagram_sectors : GoniometricDiagram::kDefaultSectors;
    }
    const ModelOptions& options_;
    std::optional<DiagramEstimate> estimate_;
    std::vector<std::unique_ptr<GoniometricDiagram>> histograms_;
};

}  // namespace

LightModel build_model(const std::string& ray_file, const ModelOptions& options, const BuildProgress& progress) {
    std::optional<tbb::global_control> threads;
    if (options.threads > 0) threads.emplace(tbb::global_control::max_allowed_parallelism, size_t(options.threads));
    auto report = [&](int pass, double f) {
        if (progress) progress(pass, f);
    };

    LightModel model;
    model.options = options;
    model.bins.width_nm = options.spectral_bin_nm;
    model.bins.count = std::max(1, int(std::lround(400 / options.spectral_bin_nm)));

    // Pass 1: bounds and count.
    Box bounds;
    double scale = 1;
    {
        auto reader = open_rays(ray_file);
        const RayHeader& header = reader->header();
        scale = millimetres_per(header.unit);
        model.source.path = ray_file;
        model.source.format = to_string(header.format);
        model.source.unit = to_string(header.unit);
        RayChunk chunk;
        while (reader->read(chunk)) {
            for (const Ray& r : chunk.rays) bounds.extend({r.origin.x * scale, r.origin.y * scale, r.origin.z * scale});
            report(1, reader->progress());
        }
        model.source.rays = reader->totals().rays;
        model.source.radiant = header.has_radiant ? reader->totals().radiant : std::nan("");
    }
    if (model.source.rays == 0) throw Error(ray_file + ": the file holds no rays to build a model from");

    const int density_resolution = options.density_resolution > 0
                                       ? options.density_resolution
                                       : adapted_resolution(model.source.rays, options.max_density_resolution);
    model.density_frame = LatticeFrame(bounds, density_resolution);
    model.flux_frame = LatticeFrame(bounds, options.flux_resolution);
    model.intensity_frame = LatticeFrame(bounds, options.intensity_resolution);
    const LatticeFrame& dframe = model.density_frame;

    // The lattices nest: a density voxel belongs to the flux cell holding its centre, a flux
    // cell to the intensity cell holding its centre (the three resolutions need not divide each
    // other). A ray's flux and its direction so land in the same cell's flux and diagram.
    const size_t voxel_count = size_t(dframe.cell_count());
    std::vector<int32_t> voxel_flux_cell(voxel_count), voxel_intensity_cell(voxel_count);
    for (int32_t z = 0; z < dframe.dims()[2]; ++z)
        for (int32_t y = 0; y < dframe.dims()[1]; ++y)
            for (int32_t x = 0; x < dframe.dims()[0]; ++x) {
                const Coord c{x, y, z};
                const Coord flux_cell = model.flux_frame.cell_of(dframe.cell_centre(c));
                voxel_flux_cell[size_t(dframe.linear(c))] = int32_t(model.flux_frame.linear(flux_cell));
                voxel_intensity_cell[size_t(dframe.linear(c))] = int32_t(
                    model.intensity_frame.linear(model.intensity_frame.cell_of(model.flux_frame.cell_centre(flux_cell))));
            }

    // Pass 2: density, flux, spectra, diagrams.
    DensityLattice density(dframe);
    const size_t flux_cells = size_t(model.flux_frame.cell_count());
    const size_t intensity_cells = size_t(model.intensity_frame.cell_count());
    const int bin_count = model.bins.count;
    tbb::enumerable_thread_specific<Accumulator> accumulators([&] {
        Accumulator a;
        a.flux.assign(flux_cells, 0);
        a.luminous.assign(flux_cells, 0);
        a.spectrum.assign(flux_cells * size_t(bin_count), 0);
        return a;
    });
    std::vector<int32_t> voxel_of_ray;
    std::vector<Vec3> origins;
    DiagramRays diagram_rays(options, intensity_cells);
    bool luminous_known = false, spectral = false;
    {
        auto reader = open_rays(ray_file);
        const RayHeader& header = reader->header();
        const PhotometricWeights photometric(header);
        luminous_known = photometric.luminous_known();
        const RayFlux flux_of{header.has_radiant};
        model.flux_unit = header.has_radiant ? "W" : "lm";
        const auto tables = table_bins(header, model.bins);
        spectral = header.spectral != SpectralKind::none;
        RayChunk chunk;
        while (reader->read(chunk)) {
            const size_t n = chunk.size();
            origins.resize(n);
            voxel_of_ray.resize(n);
            tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 4096), [&](const tbb::blocked_range<size_t>& range) {
                Accumulator& acc = accumulators.local();
                for (size_t i = range.begin(); i != range.end(); ++i) {
                    const Ray& r = chunk.rays[i];
                    const Vec3 p{r.origin.x * scale, r.origin.y * scale, r.origin.z * scale};
                    origins[i] = p;
                    const int64_t v = dframe.linear(dframe.cell_of(p));
                    const size_t fc = size_t(voxel_flux_cell[size_t(v)]);
                    const double phi = flux_of(r);
                    acc.flux[fc] += phi;
                    if (luminous_known) acc.luminous[fc] += photometric.luminous(r);
                    double* spectrum = &acc.spectrum[fc * size_t(bin_count)];
                    if (r.spectrum >= 0) {
                        const auto& f = tables[size_t(r.spectrum)];
                        for (int b = 0; b < bin_count; ++b) spectrum[b] += phi * f[size_t(b)];
                    } else {
                        const float wl = header.spectral == SpectralKind::single_wavelength ? header.single_wavelength
                                         : header.spectral == SpectralKind::shared_table     ? kUnknown
                                                                                             : r.wavelength;
                        if (header.spectral == SpectralKind::shared_table && !tables.empty()) {
                            for (int b = 0; b < bin_count; ++b) spectrum[b] += phi * tables[0][size_t(b)];
                        } else if (const int b = model.bins.bin_of(wl); b >= 0) {
                            spectrum[b] += phi;
                        }
                    }
                    voxel_of_ray[i] = int32_t(v);
                }
            });
            // Directions one thread at a time: a histogram per cell and thread would not fit.
            for (size_t i = 0; i < n; ++i) {
                const Ray& r = chunk.rays[i];
                diagram_rays.add(size_t(voxel_intensity_cell[size_t(voxel_of_ray[i])]),
                                 {r.direction.x, r.direction.y, r.direction.z}, flux_of(r));
            }
            density.add(origins);
            report(2, reader->progress());
        }
    }

    // Merge the threads' accumulators.
    Accumulator total;
    total.flux.assign(flux_cells, 0);
    total.luminous.assign(flux_cells, 0);
    total.spectrum.assign(flux_cells * size_t(bin_count), 0);
    for (const Accumulator& a : accumulators) {
        for (size_t c = 0; c < flux_cells; ++c) {
            total.flux[c] += a.flux[c];
            total.luminous[c] += a.luminous[c];
        }
        for (size_t i = 0; i < total.spectrum.size(); ++i) total.spectrum[i] += a.spectrum[i];
    }

    // Luminous flux of the rays: their luminous column, or their radiant flux weighted by V(lambda).
    model.source.luminous = std::nan("");
    if (luminous_known) {
        model.source.luminous = 0;
        for (double l : total.luminous) model.source.luminous += l;
    }

    // Occupied voxels grouped by flux cell; flux cells and diagrams that hold light.
    std::vector<std::vector<Coord>> voxels_of_cell(flux_cells);
    std::vector<std::vector<float>> counts_of_cell(flux_cells);
    const openvdb::FloatGrid::Ptr density_grid = density.grid();
    for (auto it = density_grid->cbeginValueOn(); it; ++it) {
        if (!(*it > 0)) continue;
        const Coord c{it.getCoord().x(), it.getCoord().y(), it.getCoord().z()};
        const size_t fc = size_t(voxel_flux_cell[size_t(dframe.linear(c))]);
        voxels_of_cell[fc].push_back(c);
        counts_of_cell[fc].push_back(*it);
    }
    std::vector<int32_t> diagram_index(intensity_cells, -1);
    std::vector<size_t> diagram_of;  // intensity cell of each diagram
    for (size_t fc = 0; fc < flux_cells; ++fc) {
        if (!(total.flux[fc] > 0) || voxels_of_cell[fc].empty()) continue;
        FluxCell cell;
        cell.coord = {int32_t(fc % model.flux_frame.dims()[0]),
                      int32_t(fc / model.flux_frame.dims()[0] % model.flux_frame.dims()[1]),
                      int32_t(fc / (size_t(model.flux_frame.dims()[0]) * model.flux_frame.dims()[1]))};
        cell.flux = total.flux[fc];
        cell.luminous = luminous_known ? total.luminous[fc] : std::nan("");
        const size_t k = size_t(voxel_intensity_cell[size_t(dframe.linear(voxels_of_cell[fc][0]))]);
        if (diagram_index[k] < 0) {
            diagram_index[k] = int32_t(diagram_of.size());
            diagram_of.push_back(k);
            model.diagram_cells.push_back({int32_t(k % model.intensity_frame.dims()[0]),
                                           int32_t(k / model.intensity_frame.dims()[0] % model.intensity_frame.dims()[1]),
                                           int32_t(k / (size_t(model.intensity_frame.dims()[0]) * model.intensity_frame.dims()[1]))});
        }
        cell.intensity_cell = diagram_index[k];
        cell.first_voxel = uint32_t(model.voxels.size());
        cell.voxel_count = uint32_t(voxels_of_cell[fc].size());
        model.voxels.insert(model.voxels.end(), voxels_of_cell[fc].begin(), voxels_of_cell[fc].end());
        model.voxel_density.insert(model.voxel_density.end(), counts_of_cell[fc].begin(), counts_of_cell[fc].end());
        double spectrum_sum = 0;
        for (int b = 0; b < bin_count; ++b) spectrum_sum += total.spectrum[fc * size_t(bin_count) + size_t(b)];
        for (int b = 0; b < bin_count; ++b)
            model.spectra.push_back(spectral && spectrum_sum > 0
                                        ? float(total.spectrum[fc * size_t(bin_count) + size_t(b)] / spectrum_sum)
                                        : 0.f);
        model.flux_cells.push_back(cell);
    }
    if (model.flux_cells.empty()) throw Error(ray_file + ": the rays carry no flux to build a model from");
    model.diagrams = diagram_rays.diagrams(diagram_of);

    // Pass 3: a reservoir sample of the origins in each boundary voxel, then the sphere fits.
    model.boundary_voxels = density.boundary_cells();
    std::vector<int32_t> boundary_slot(voxel_count, -1);
    for (size_t b = 0; b < model.boundary_voxels.size(); ++b)
        boundary_slot[size_t(dframe.linear(model.boundary_voxels[b]))] = int32_t(b);
    const size_t per_cell = size_t(std::max(1, options.samples_per_cell));
    std::vector<Vec3> samples(model.boundary_voxels.size() * per_cell);
    std::vector<uint64_t> seen(model.boundary_voxels.size(), 0);
    {
        Pcg32 rng(options.seed);
        auto reader = open_rays(ray_file);
        RayChunk chunk;
        while (reader->read(chunk)) {
            for (const Ray& r : chunk.rays) {
                const Vec3 p{r.origin.x * scale, r.origin.y * scale, r.origin.z * scale};
                const int32_t slot = boundary_slot[size_t(dframe.linear(dframe.cell_of(p)))];
                if (slot < 0) continue;
                const uint64_t k = seen[size_t(slot)]++;
                if (k < per_cell) {
                    samples[size_t(slot) * per_cell + k] = p;
                } else if (const uint64_t j = uint64_t(rng.uniform() * double(k + 1)); j < per_cell) {
                    samples[size_t(slot) * per_cell + j] = p;
                }
            }
            report(3, reader->progress());
        }
    }
    std::vector<double> boundary_counts(model.boundary_voxels.size());
    for (size_t b = 0; b < boundary_counts.size(); ++b) boundary_counts[b] = double(seen[b]);
    const double reference = reference_count(boundary_counts);
    std::vector<std::vector<Sphere>> fitted(model.boundary_voxels.size());
    tbb::parallel_for(size_t(0), model.boundary_voxels.size(), [&](size_t b) {
        const size_t n = size_t(std::min<uint64_t>(seen[b], per_cell));
        if (n == 0) return;
        const std::vector<Vec3> cell_samples(samples.begin() + std::ptrdiff_t(b * per_cell),
                                             samples.begin() + std::ptrdiff_t(b * per_cell + n));
        const int k = spheres_for_count(double(seen[b]), reference, options.max_spheres_per_cell);
        fitted[b] = fit_cell_spheres(dframe.cell_lower(model.boundary_voxels[b]), dframe.cell_size(), cell_samples, k);
    });
    for (const auto& s : fitted) model.spheres.insert(model.spheres.end(), s.begin(), s.end());
    measure_visible_fractions(model, options.coverage_lines, options.seed);
    report(4, 1);
    return model;
}

}  // namespace rayset::lightmodel
