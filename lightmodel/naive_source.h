// The naive ray-set emitter of the paper's Figure 1: photons are the file's own rays, chosen
// in proportion to their flux. It has no body (a camera never sees it) and cannot be light
// sampled, which is exactly what the complex model fixes; the tracer keeps it for comparisons.
// Holds every ray in memory (28 bytes each).
#pragma once

#include "core/alias_table.h"
#include "lightmodel/emitter.h"

#include <string>
#include <vector>

namespace rayset::lightmodel {

class NaiveRaySource : public Emitter {
public:
    explicit NaiveRaySource(const std::string& ray_file);

    size_t ray_count() const { return origins_.size(); }
    double phi(const SpectralSelect& select = {}) const override;
    Box bounds() const override { return bounds_; }
    Rgb phi_colour() const override;
    bool intersect(Vec3, Vec3, double, EmitterHit&) const override { return false; }
    double L(Vec3, Vec3, const EmitterHit&, const SpectralSelect& = {}) const override { return 0; }
    Rgb L_colour(Vec3, Vec3, const EmitterHit&) const override { return {}; }
    void L_spectral(Vec3, Vec3, const EmitterHit&, SpectralQuery&) const override {}
    BinnedSpectrum phi_spectrum() const override { return {}; }
    std::optional<LiSample> sample_Li(Vec3, double, double, Vec3, const SpectralSelect& = {},
                                      SpectralQuery* = nullptr,
                                      BodyEntry = BodyEntry::wanted) const override {
        return std::nullopt;
    }
    double pdf_Li(Vec3, Vec3) const override { return 0; }
    // u[0] picks the ray; the rest are unused. The position and direction are fixed by the ray
    // (delta densities): pdf_position is the ray's probability, pdf_direction 0. A ray of known
    // wavelength emits that wavelength alone; one without, a D65-shaped spectrum.
    LeSample sample_Le(const double u[7], const SpectralSelect& select = {}) const override;
    void pdf_Le(Vec3, Vec3, double& pdf_position, double& pdf_direction) const override {
        pdf_position = pdf_direction = 0;
    }
    double pdf_Le_line(Vec3, Vec3) const override { return 0; }

private:
    std::vector<Vec3> origins_, directions_;
    std::vector<float> flux_, luminous_;
    std::vector<int16_t> band_;      // spectral bin of the ray's wavelength, -1 unknown
    std::vector<float> wavelength_;  // nm, NaN unknown
    BinnedSpectrum grey_;            // of rays without a wavelength
    AliasTable rays_;                // the rays, drawn by flux
    double total_flux_ = 0;
    SpectralBins bins_;
    // Colour of a unit of flux of each ray's spectral bin at 1 lm per unit (index bin + 1; 0:
    // unknown wavelength, grey), scaled per ray by its efficacy.
    std::vector<Rgb> band_colour_;
    bool luminous_known_ = false;
    double default_efficacy_ = kRgbLumensPerWatt;
    Rgb ray_colour(size_t i) const;  // of the ray's whole flux
    Box bounds_;
};

}  // namespace rayset::lightmodel
