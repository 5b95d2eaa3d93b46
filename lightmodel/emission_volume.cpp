#include "lightmodel/emission_volume.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rayset::lightmodel {

int SpectralBins::bin_of(double wavelength_nm) const {
    if (std::isnan(wavelength_nm)) return -1;
    return std::clamp(int(std::floor((wavelength_nm - first_nm) / width_nm)), 0, count - 1);
}

double LightModel::total_flux() const {
    double sum = 0;
    for (const FluxCell& c : flux_cells) sum += c.flux;
    return sum;
}

double LightModel::total_luminous() const {
    double sum = 0;
    for (const FluxCell& c : flux_cells) sum += c.luminous;
    return sum;
}

Box LightModel::bounds() const {
    Box box;
    for (const Sphere& s : spheres) {
        box.extend({s.x - s.r, s.y - s.r, s.z - s.r});
        box.extend({s.x + s.r, s.y + s.r, s.z + s.r});
    }
    return box;
}

EmissionVolume::EmissionVolume(const LightModel& model) : model_(model) {
    const LatticeFrame& frame = model.density_frame;
    voxel_cell_.assign(size_t(frame.cell_count()), -1);
    for (uint32_t c = 0; c < model.flux_cells.size(); ++c) {
        const FluxCell& cell = model.flux_cells[c];
        for (uint32_t v = cell.first_voxel; v < cell.first_voxel + cell.voxel_count; ++v)
            voxel_cell_[size_t(frame.linear(model.voxels[v]))] = int32_t(c);
    }
    voxel_volume_ = std::pow(frame.cell_size(), 3);
    std::vector<double> fluxes(model.flux_cells.size());
    for (size_t c = 0; c < model.flux_cells.size(); ++c) {
        fluxes[c] = model.flux_cells[c].flux;
        total_flux_ += fluxes[c];
    }
    if (total_flux_ > 0) cells_ = AliasTable(fluxes);
    line_terms_.resize(model.flux_cells.size());
    for (uint32_t c = 0; c < model.flux_cells.size(); ++c) {
        const FluxCell& cell = model.flux_cells[c];
        line_terms_[c] = {cell.flux, 1 / (cell_volume(c) * cell.visible_fraction),
                          cell.flux / total_flux_ / cell_volume(c), cell.intensity_cell};
    }
    cell_colour_ = cell_colours(model);
    cell_spectrum_ = cell_spectra(model);
}

BinnedSpectrum EmissionVolume::total_spectrum() const {
    std::array<double, kSpectrumBins> sum{};
    for (uint32_t c = 0; c < model_.flux_cells.size(); ++c) {
        const double weight = model_.flux_cells[c].flux * luminance(cell_colour_[c]);
        for (int k = 0; k < kSpectrumBins; ++k)
            sum[size_t(k)] += weight * cell_spectrum_[c].value(k);
    }
    return BinnedSpectrum(sum);
}

Rgb EmissionVolume::total_colour() const {
    Rgb sum;
    for (uint32_t c = 0; c < model_.flux_cells.size(); ++c)
        sum += model_.flux_cells[c].flux * cell_colour_[c];
    return sum;
}

double EmissionVolume::cell_flux(uint32_t cell, const SpectralSelect& select) const {
    if (select.whole_flux()) return line_terms_[cell].flux;
    const FluxCell& c = model_.flux_cells[cell];
    if (select.quantity == SpectralSelect::luminous) return c.luminous;
    return c.flux * model_.spectra[size_t(cell) * model_.bins.count + select.band];
}

double EmissionVolume::total(const SpectralSelect& select) const {
    double sum = 0;
    for (uint32_t c = 0; c < model_.flux_cells.size(); ++c) sum += cell_flux(c, select);
    return sum;
}

double EmissionVolume::cell_volume(uint32_t cell) const {
    return model_.flux_cells[cell].voxel_count * voxel_volume_;
}

double EmissionVolume::radiance_toward(Vec3 origin, Vec3 dir, double tmin, double tmax,
                                       const SpectralSelect& select, const LineAlso& also) const {
    const double inf = std::numeric_limits<double>::infinity();
    const bool whole_line = also.line_density != nullptr;
    double sum = 0, pdf_sum = 0, line_sum = 0;
    Rgb colour_sum;
    // Neighbouring voxels mostly share an intensity cell: its diagram is evaluated once for them.
    int32_t diagram = -1;
    double d = 0;
    traverse(origin, dir, whole_line ? -inf : tmin, whole_line ? inf : tmax,
             [&](uint32_t c, double t0, double t1) {
                 const LineTerms& cell = line_terms_[c];
                 if (cell.diagram != diagram) {
                     diagram = cell.diagram;
                     d = model_.diagrams[size_t(diagram)].pdf(-dir);
                 }
                 if (whole_line) {
                     line_sum += line_term(c, d, t0, t1);
                     t0 = std::max(t0, tmin), t1 = std::min(t1, tmax);
                     if (!(t1 > t0)) return;
                 }
                 sum += emission(c, d * cell.emission * (t1 - t0), select,
                                 also.colour ? &colour_sum : nullptr, also.spectral);
                 if (also.pdf) pdf_sum += direction_density(c, t0, t1);
             });
    if (also.colour) *also.colour = colour_sum;
    if (also.pdf) *also.pdf = pdf_sum;
    if (whole_line) *also.line_density = line_sum;
    return sum;
}

double EmissionVolume::point_estimate(uint32_t c, Vec3 dir, double distance, double scale,
                                      const SpectralSelect& select, Rgb* colour,
                                      SpectralQuery* spectral) const {
    const LineTerms& cell = line_terms_[c];
    const double d = model_.diagrams[size_t(cell.diagram)].pdf(-dir);
    const double per_flux = scale * d * cell.emission / (cell.point_density * distance * distance);
    if (colour) *colour = Rgb{};
    return emission(c, per_flux, select, colour, spectral);
}

double EmissionVolume::emission(uint32_t c, double per_flux, const SpectralSelect& select,
                                Rgb* colour, SpectralQuery* spectral) const {
    const LineTerms& cell = line_terms_[c];
    if (colour) *colour += (cell.flux * per_flux) * cell_colour_[c];
    if (spectral) {
        const double weight = cell.flux * per_flux * luminance(cell_colour_[c]);
        for (int i = 0; i < 4; ++i)
            spectral->value[i] += weight * cell_spectrum_[c](spectral->nm[i]);
    }
    return cell_flux(c, select) * per_flux;
}

double EmissionVolume::point_density(uint32_t cell) const {
    return line_terms_[cell].point_density;
}

double EmissionVolume::direction_density(uint32_t cell, double t0, double t1) const {
    return line_terms_[cell].point_density * (t1 * t1 * t1 - t0 * t0 * t0) * (1.0 / 3);
}

double EmissionVolume::pdf_direction(Vec3 origin, Vec3 dir) const {
    double sum = 0;
    traverse(origin, dir, 0, std::numeric_limits<double>::infinity(),
             [&](uint32_t c, double t0, double t1) { sum += direction_density(c, t0, t1); });
    return sum;
}

double EmissionVolume::line_density(Vec3 origin, Vec3 dir) const {
    const double inf = std::numeric_limits<double>::infinity();
    double sum = 0, d = 0;
    int32_t diagram = -1;
    traverse(origin, dir, -inf, inf, [&](uint32_t c, double t0, double t1) {
        const int32_t k = line_terms_[c].diagram;
        if (k != diagram) diagram = k, d = model_.diagrams[size_t(k)].pdf(-dir);
        sum += line_term(c, d, t0, t1);
    });
    return sum;
}

VolumeSample EmissionVolume::sample_point(double u_cell, double u_voxel, Vec3 u_point) const {
    const uint32_t c = uint32_t(cells_.sample(u_cell).index);
    VolumeSample s;
    s.voxel = voxel_in_cell(c, u_voxel);
    s.point = point_in_voxel(s.voxel, u_point);
    s.flux_cell = c;
    s.pdf_volume = point_density(c);
    return s;
}

Vec3 EmissionVolume::sample_in_cell(uint32_t c, double u_voxel, Vec3 u_point) const {
    return point_in_voxel(voxel_in_cell(c, u_voxel), u_point);
}

uint32_t EmissionVolume::voxel_in_cell(uint32_t c, double u_voxel) const {
    const FluxCell& cell = model_.flux_cells[c];
    return cell.first_voxel + std::min(uint32_t(u_voxel * cell.voxel_count), cell.voxel_count - 1);
}

Vec3 EmissionVolume::point_in_voxel(uint32_t voxel, Vec3 u_point) const {
    const double h = model_.density_frame.cell_size();
    return model_.density_frame.cell_lower(model_.voxels[voxel]) +
           Vec3{u_point.x * h, u_point.y * h, u_point.z * h};
}

int32_t EmissionVolume::cell_at(Vec3 point) const {
    const LatticeFrame& frame = model_.density_frame;
    const double h = frame.cell_size();
    const Vec3 q = point - frame.origin();
    const Coord c{int32_t(std::floor(q.x / h)), int32_t(std::floor(q.y / h)),
                  int32_t(std::floor(q.z / h))};
    if (!frame.contains(c)) return -1;
    return voxel_cell_[size_t(frame.linear(c))];
}

double EmissionVolume::pdf_point(Vec3 point) const {
    const int32_t c = cell_at(point);
    return c < 0 ? 0 : point_density(uint32_t(c));
}

}  // namespace rayset::lightmodel
