// POV-Ray's fog, read as a medium between the eye and what it sees: along each segment of an
// eye path it dims what lies beyond and adds its own colour as radiance.
//
// Over a segment of length d (infinite toward the sky) of optical depth tau, POV-Ray's result
// is, per channel, T ((1 - f) + f F) C + (1 - T) F, with T = max(exp(-tau), t), C what lies
// beyond, F the fog colour and f, t its filter and transmit (read back from POV-Ray 3.7's
// renders). tau is d / distance for constant fog; for ground fog (fog_type 2) the density along
// `up` is 1 below fog_offset and 1 / (1 + ((h - fog_offset) / fog_alt)^2) above it (measured
// from POV-Ray: at fog_alt it is 50%, where the manual says 25%), integrated in closed form.
// Light arriving from light sources is not dimmed (shadow rays see no fog), as in POV-Ray:
// fog is how a scene looks through haze, not a participating medium of its lighting.
//
// Fog turbulence, read back from POV-Ray's renders of constant and ground fog: a segment's
// optical depth is scaled by 1 - exp(-d / distance) min(1, turb_depth X), with X a turbulence
// sum_i omega^i noise(lambda^i q) at q = p * turbulence (component by component), p the point
// turb_depth of the way along the segment in the fog's own coordinates; X has the mean of
// noise.h's sum and twice its spread, as POV-Ray's. It thins the fog in patches, the more so on
// short segments; a segment to the sky keeps its depth.
#pragma once

#include <vector>

#include "tracer/render/colour_decoding.h"
#include "tracer/render/rgb.h"
#include "tracer/scene_language/scene_description.h"

namespace rayset::tracer {

class FogMedium {
public:
    // Refuses (Error, "not supported: ...") more than one fog.
    // `to_internal` converts W/(m^2 sr) to the renderer's radiance unit (units.h).
    FogMedium(const SceneDescription& scene, double to_internal);

    bool present() const { return present_; }
    // Along (origin, unit direction) for `length` (infinity: to the sky): the factor on what
    // lies beyond, and the radiance the fog adds in front of it.
    void along(Vec3 origin, Vec3 direction, double length, Rgb& through, Rgb& added) const;
    // The optical depth of that segment.
    double optical_depth(Vec3 origin, Vec3 direction, double length) const;

private:
    // The turbulence's factor on the optical depth of a finite segment, and the depth without
    // turbulence.
    double turbulence_factor(Vec3 origin, Vec3 direction, double length) const;
    double untroubled_depth(Vec3 origin, Vec3 direction, double length) const;

    bool present_ = false;
    bool ground_ = false;
    double distance_ = 1, offset_ = 0, altitude_ = 1;
    Vec3 up_{0, 1, 0};
    Rgb colour_;         // decoded, linear
    Rgb tint_{1, 1, 1};  // what is beyond is seen through: (1 - filter) + filter x colour
    double transmit_ = 0;
    double to_internal_ = 1;
    bool turbulent_ = false;
    Vec3 turbulence_;
    double turb_depth_ = 0.5, omega_ = 0.5, lambda_ = 2;
    int octaves_ = 6, noise_generator_ = 2;
    Matrix4 world_to_fog_;
};

}  // namespace rayset::tracer
