// What fills the inside of objects: POV-Ray's interior fade (fade_distance, fade_power,
// fade_color) read as Beer-Lambert absorption, and its homogeneous media (absorption, emission,
// scattering of the five types), which add up. Coefficients are per scene unit, as POV-Ray
// writes them; path lengths are in scene units too.
//
// Fade. POV-Ray 3.7 scales light that travelled d inside by, per channel (read back from its
// renders), fade_color + (1 - fade_color) / (1 + (d / fade_distance)^fade_power) for fade_power
// below 1000, and exp(-(1 - fade_color) d / fade_distance) from 1000 on. The second is
// Beer-Lambert and is kept exactly: absorption (1 - fade_color) / fade_distance. The first is
// not (it never falls below fade_color, and two halves of a path do not multiply to the whole);
// it is read as the Beer-Lambert absorption that transmits what POV-Ray transmits at
// fade_distance, where both say the light is halfway to fade_color:
// -ln((1 + fade_color) / 2) / fade_distance. Shorter paths transmit a little more than POV-Ray
// shows, longer ones less, down to black instead of fade_color.
//
// Density. `density { }` scales a medium's absorption, emission and scattering by its colour
// (channel by channel) at each point, several densities multiplying, as POV-Ray's patterns give
// it (evaluate_pigment of the scene language). Such media are sampled by delta tracking under a
// majorant, the product of the densities' largest map entries times the extinction: exact
// (unbiased) whatever the pattern, as the colour map bounds its values.
//
// Which medium a path segment lies in: the object it entered at its start, else the object
// whose surface it leaves at its end (its outward normal along the ray). That is exact for
// closed objects, one inside another included; a segment that leaves an inner object and meets
// a third one before the outer one's surface is taken to be in no medium.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "core/random.h"
#include "tracer/render/colour_decoding.h"
#include "tracer/render/phase_function.h"
#include "tracer/render/rgb.h"
#include "tracer/render/sampling.h"
#include "tracer/scene_language/scene_description.h"

namespace rayset::tracer {

struct SurfaceHit;

// Where a free flight ends along a segment, what it brings, and the factor on the path's
// throughput.
struct FreeFlight {
    bool scattered = false;  // true: at distance t, where the medium scatters the path
    double t = 0;
    // If scattered, the factor up to the scattering (the scattering itself is the phase
    // sample's, scattered()); else the factor on what lies beyond the segment.
    Rgb weight;
    Rgb emitted;  // the medium's emission seen on the way, per unit throughput at the start
};

class InteriorMedium {
public:
    InteriorMedium() = default;
    // The interior's fade and media; refuses (Error, "not supported: ...") what is not
    // rendered: densities the scene language cannot evaluate (density_file, ...), fade colours
    // outside 0..1, negative coefficients. `to_internal` converts POV-Ray's emission
    // (W/(m^2 sr) per scene unit of path) to the renderer's radiance unit (units.h).
    InteriorMedium(const InteriorRef& interior, double to_internal, const ColourDecoding& decoding);
    // The scene's atmospheric media, added together.
    InteriorMedium(const std::vector<AtmosphericMedia>& media, double to_internal,
                   const ColourDecoding& decoding);

    bool present() const { return !parts_.empty(); }
    // Whether it scatters or emits: more than an attenuation of what passes.
    bool participates() const { return scatters_ || emits_; }

    // The transmittance along a segment (origin, unit direction, length; infinite: the whole
    // way): exact where the medium is uniform, else ratio tracking under the majorant (an
    // unbiased estimate; draws from `rng`).
    Rgb transmittance(Vec3 origin, Vec3 direction, double length, Pcg32& rng) const;
    // A free flight along that segment: the exponential of a channel's extinction chosen at
    // random (the pdf the three channels' mixture) where the medium is uniform, its emission in
    // closed form; else delta tracking under the majorant with null collisions (weighted),
    // emission collected at each tentative collision.
    FreeFlight fly(Vec3 origin, Vec3 direction, double length, Pcg32& rng) const;

    // sigma_s p(cos_theta) at `point` summed over the media: the fraction scattered per unit
    // length into a unit solid angle at that angle from the direction of travel.
    Rgb scattered(Vec3 point, double cos_theta) const;
    // The pdf of sample_phase's directions (the phase functions mixed by their mean scattering
    // without density).
    double phase_pdf(double cos_theta) const;
    Vec3 sample_phase(Vec3 forward, double u_choice, double u1, double u2) const;

private:
    // One media { } (or the fade): its coefficients where its densities are 1.
    struct Part {
        Rgb extinction, scattering, emission;
        PhaseFunction phase;
        double phase_share = 0;
        std::vector<const Pigment*> densities;  // multiplied; none: 1 everywhere
        Rgb density_bound{1, 1, 1};             // the densities' product never exceeds it
        Rgb density(Vec3 point) const;
    };
    struct Local {
        Rgb extinction, scattering, emission;
    };
    static Part part_of(const Media& media, double to_internal, const ColourDecoding& decoding);
    Local at(Vec3 point) const;
    void sum_parts();
    FreeFlight fly_uniform(double length, Pcg32& rng) const;
    Rgb uniform_transmittance(double length) const;
    Rgb uniform_emitted(double length) const;

    InteriorRef keep_;  // what the densities point into
    std::vector<Part> parts_;
    bool uniform_ = true, scatters_ = false, emits_ = false;
    Rgb extinction_, emission_;  // summed, where uniform
    double majorant_ = 0;        // of the extinction, every channel, where not uniform
};

// The media of the scene's objects, by object index, and the rule of which one a segment
// lies in (above); atmospheric media (media { } at the top level) fill what lies outside
// objects and inside hollow objects, as in POV-Ray, as one more medium after the objects'.
class Interiors {
public:
    // A path inside an object that holds no medium and is not hollow: no medium, not even the
    // atmosphere.
    static constexpr int kNoMedium = -2;

    Interiors() = default;
    // Refuses fade and media on objects without an inside (triangles, meshes, discs,
    // polygons, patches) and on parts of solids with an interior of their own; atmospheric
    // media with density, emitting without extinction (infinitely bright toward the sky),
    // together with fade or media in objects, or with illuminance receivers.
    Interiors(const SceneDescription& scene, double to_internal);

    bool any() const { return any_; }
    // Whether some medium scatters or emits (only the path integrator renders that).
    bool participating() const { return participating_; }
    const InteriorMedium& medium(int object) const { return media_[size_t(object)]; }

    // The medium of a segment along `direction` that started in `start` (-1: none known,
    // kNoMedium: none) and ends at `hit` (if `found`): an index or -1.
    int segment_medium(int start, Vec3 direction, bool found, const SurfaceHit& hit) const;
    // The medium a path is in after turning at `hit` from `direction` to `wi`, given the one it
    // came through.
    int medium_after(int segment, Vec3 direction, const SurfaceHit& hit, Vec3 wi) const;

private:
    std::vector<InteriorMedium> media_;  // by object; then the atmosphere's, if any
    std::vector<uint8_t> hollow_;        // by object
    int outside_ = -1;                   // the atmosphere's index, or -1
    bool any_ = false, participating_ = false;
};

}  // namespace rayset::tracer
