// POV-Ray's five media scattering types as phase functions normalised to integrate to 1 over
// the sphere, with exact sampling of each. The angle is between the light's direction of travel
// before and after scattering: cos_theta = 1 is straight on (forward scattering).
//
//   1 isotropic                 1 / (4 pi)
//   2 Mie hazy                  (1 + 9 x^8) / (8 pi),                 x = (1 + cos_theta) / 2
//   3 Mie murky                 (1 + 50 x^32) / (2 pi (2 + 100 / 33))
//   4 Rayleigh                  3 (1 + cos_theta^2) / (16 pi)
//   5 Henyey-Greenstein         (1 - g^2) / (4 pi (1 + g^2 - 2 g cos_theta)^(3/2)), g the
//                               eccentricity (g > 0 forward)
//
// POV-Ray's shapes are these; their normalisation to 1 makes the scattering colour the
// scattering coefficient (the fraction of light scattered per unit length), so a medium that
// only scatters keeps the light's energy.
#pragma once

#include <cmath>

#include "tracer/render/sampling.h"

namespace rayset::tracer {

class PhaseFunction {
public:
    PhaseFunction() = default;
    // `type` 1 to 5 as POV-Ray numbers them; `eccentricity` for type 5.
    PhaseFunction(int type, double eccentricity) : type_(type), g_(eccentricity) {}

    double eval(double cos_theta) const {
        switch (type_) {
            case 2: return (1 + 9 * std::pow((1 + cos_theta) / 2, 8)) / (8 * kPi);
            case 3:
                return (1 + 50 * std::pow((1 + cos_theta) / 2, 32)) / (2 * kPi * kMurkyIntegral);
            case 4: return 3 * (1 + cos_theta * cos_theta) / (16 * kPi);
            case 5: {
                const double denominator = 1 + g_ * g_ - 2 * g_ * cos_theta;
                return (1 - g_ * g_) / (4 * kPi * denominator * std::sqrt(denominator));
            }
            default: return 1 / (4 * kPi);
        }
    }

    // A direction scattered from light travelling along `forward` (unit); its pdf is
    // eval(dot(result, forward)).
    Vec3 sample(Vec3 forward, double u_choice, double u1, double u2) const {
        const double cos_theta = sample_cos(u_choice, u1);
        const double sin_theta = std::sqrt(std::max(0.0, 1 - cos_theta * cos_theta));
        const double phi = 2 * kPi * u2;
        return Frame(forward).to_world(
            {sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta});
    }

private:
    // The integral over cos_theta in [-1, 1] of murky's 1 + 50 x^32: 2 + 100 / 33.
    static constexpr double kMurkyIntegral = 2 + 100.0 / 33;

    // The hazy, murky and Rayleigh shapes are a constant plus a power: a mixture of a uniform
    // cos_theta (chosen with the constant's share of the integral) and that power's own
    // inverse distribution.
    double sample_cos(double u_choice, double u) const {
        switch (type_) {
            case 2: return u_choice < 0.5 ? 2 * u - 1 : 2 * std::pow(u, 1.0 / 9) - 1;
            case 3:
                return u_choice < 2 / kMurkyIntegral ? 2 * u - 1 : 2 * std::pow(u, 1.0 / 33) - 1;
            case 4: return u_choice < 0.75 ? 2 * u - 1 : std::cbrt(2 * u - 1);
            case 5: {
                if (std::fabs(g_) < 1e-4) return 2 * u - 1;
                const double k = (1 - g_ * g_) / (1 - g_ + 2 * g_ * u);
                return std::clamp((1 + g_ * g_ - k * k) / (2 * g_), -1.0, 1.0);
            }
            default: return 2 * u - 1;
        }
    }

    int type_ = 1;
    double g_ = 0;
};

}  // namespace rayset::tracer
