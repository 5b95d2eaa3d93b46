#include "lightmodel/naive_source.h"

#include "converters/colour/spectrum.h"
#include "converters/rays/ray_stream.h"

#include <algorithm>
#include <cmath>

namespace rayset::lightmodel {

NaiveRaySource::NaiveRaySource(const std::string& ray_file) {
    auto reader = open_rays(ray_file);
    const RayHeader& header = reader->header();
    const PhotometricWeights photometric(header);
    const double scale = millimetres_per(header.unit);
    RayChunk chunk;
    std::vector<double> weights;
    while (reader->read(chunk)) {
        for (const Ray& r : chunk.rays) {
            const Vec3 o{r.origin.x * scale, r.origin.y * scale, r.origin.z * scale};
            origins_.push_back(o);
            directions_.push_back({r.direction.x, r.direction.y, r.direction.z});
            const double phi = header.has_radiant ? r.radiant : r.luminous;
            flux_.push_back(float(phi));
            luminous_.push_back(photometric.luminous_known() ? float(photometric.luminous(r))
                                                             : 0.f);
            const float wl = header.spectral == SpectralKind::single_wavelength
                                 ? header.single_wavelength
                                 : r.wavelength;
            band_.push_back(int16_t(bins_.bin_of(wl)));
            wavelength_.push_back(wl);
            weights.push_back(phi);
            total_flux_ += phi;
            bounds_.extend(o);
        }
    }
    if (weights.empty() || !(total_flux_ > 0))
        throw Error(ray_file + ": no rays with flux to emit");
    rays_ = AliasTable(weights);
    luminous_known_ = photometric.luminous_known();
    default_efficacy_ = header.has_radiant ? kRgbLumensPerWatt : 1.0;
    grey_ = d65_spectrum();
    band_colour_.push_back(colour_per_flux({}, 1));
    for (int b = 0; b < bins_.count; ++b)
        band_colour_.push_back(colour_per_flux(bin_colour_matching(bins_, b), 1));
}

Rgb NaiveRaySource::ray_colour(size_t i) const {
    const double efficacy = luminous_known_ && flux_[i] > 0 && std::isfinite(luminous_[i])
                                ? luminous_[i] / flux_[i]
                                : default_efficacy_;
    return (efficacy * flux_[i]) * band_colour_[size_t(band_[i] + 1)];
}

Rgb NaiveRaySource::phi_colour() const {
    Rgb sum;
    for (size_t i = 0; i < flux_.size(); ++i) sum += ray_colour(i);
    return sum;
}

double NaiveRaySource::phi(const SpectralSelect& select) const {
    double sum = 0;
    for (size_t i = 0; i < flux_.size(); ++i) {
        if (select.quantity == SpectralSelect::luminous)
            sum += luminous_[i];
        else if (select.band < 0 || band_[i] == select.band)
            sum += flux_[i];
    }
    return sum;
}

LeSample NaiveRaySource::sample_Le(const double u[7], const SpectralSelect& select) const {
    const size_t i = size_t(rays_.sample(u[0]).index);
    LeSample s;
    s.origin = origins_[i];
    s.direction = directions_[i];
    s.pdf_position = flux_[i] / total_flux_;
    s.pdf_direction = 0;
    const double part = select.quantity == SpectralSelect::luminous    ? luminous_[i]
                        : (select.band < 0 || band_[i] == select.band) ? flux_[i]
                                                                       : 0.0;
    s.flux = flux_[i] > 0 ? total_flux_ * part / flux_[i] : 0;
    s.flux_colour = flux_[i] > 0 ? (total_flux_ / flux_[i]) * ray_colour(i) : Rgb{};
    if (std::isfinite(wavelength_[i]))
        s.wavelength_nm = wavelength_[i];
    else
        s.spectrum = &grey_;
    return s;
}

}  // namespace rayset::lightmodel
