// Photometric weight of rays: CIE photopic V(lambda) and the luminous flux a ray carries given
// what its file says about its spectrum.
#pragma once

#include "converters/rays/ray.h"

#include <optional>
#include <vector>

namespace rayset {

// lm/W at 555 nm (the SI definition fixes 683 lm/W at 540 THz).
inline constexpr double kMaxLuminousEfficacy = 683.002;

// CIE 1924 photopic luminous efficiency V(lambda), linearly interpolated; 0 outside its table.
double photopic_efficiency(double wavelength_nm);

// Luminous efficacy (lm/W) of radiation with the given relative spectral power table.
double luminous_efficacy(const SpectralTable& table);

// Converts between the radiant and luminous flux of individual rays of one file. Built once
// per header (it precomputes the efficacy of each spectral table).
class PhotometricWeights {
public:
    explicit PhotometricWeights(const RayHeader& header);

    // Whether luminous flux can be known for these rays: a luminous column, or radiant flux
    // with spectral information.
    bool luminous_known() const { return luminous_known_; }
    bool radiant_known() const { return radiant_known_; }
    // Luminous flux of the ray (lm): its luminous column if present, else radiant x efficacy
    // of its spectrum; NaN when unknowable (or its wavelength is unknown).
    double luminous(const Ray& ray) const;
    // Radiant flux (W): the radiant column, else luminous / efficacy where the spectrum is known.
    double radiant(const Ray& ray) const;
    // Efficacy (lm/W) the ray's spectrum has; NaN when unknown.
    double efficacy(const Ray& ray) const;
    // The efficacy every ray has when the header fixes it (one wavelength or one table; NaN if
    // unknown), or nothing when it differs from ray to ray or there is no spectrum.
    std::optional<double> shared_efficacy() const;

private:
    const RayHeader* header_;
    std::vector<double> table_efficacy_;
    double single_efficacy_ = 0;
    bool luminous_known_ = false, radiant_known_ = false;
};

}  // namespace rayset
