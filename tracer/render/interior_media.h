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
// Which medium a path segment lies in: the object it entered at its start, else the object
// whose surface it leaves at its end (its outward normal along the ray). That is exact for
// closed objects, one inside another included; a segment that leaves an inner object and meets
// a third one before the outer one's surface is taken to be in no medium.
#pragma once

#include <vector>

#include "tracer/render/colour_decoding.h"
#include "tracer/render/phase_function.h"
#include "tracer/render/rgb.h"
#include "tracer/render/sampling.h"
#include "tracer/scene_language/scene_description.h"

namespace rayset::tracer {

struct SurfaceHit;

// Where a free-flight sample ends along a segment and the factor on the path's throughput.
struct FreeFlight {
    bool scattered = false;  // true: at distance t, where the medium scatters the path
    double t = 0;
    Rgb weight;  // T(t) / pdf(t) if scattered (the scattering itself is the phase sample's);
                 // else T(length) / P(no scattering before length)
};

class InteriorMedium {
public:
    InteriorMedium() = default;
    // The interior's fade and media; refuses (Error, "not supported: ...") what is not
    // rendered: media with density, fade colours above 1. `to_internal` converts POV-Ray's
    // emission (W/(m^2 sr) per scene unit of path) to the renderer's radiance unit (units.h).
    InteriorMedium(const Interior& interior, double to_internal, const ColourDecoding& decoding);

    bool present() const { return present_; }
    // Whether it scatters or emits: more than an attenuation of what passes.
    bool participates() const { return scatters() || !is_black(emission_); }
    bool scatters() const { return !components_.empty(); }
    Rgb extinction() const { return extinction_; }
    Rgb transmittance(double length) const;
    // The radiance its emission adds to a ray along `length` (infinite: the whole way), seen
    // through the medium itself: the integral of T(s) emission over [0, length].
    Rgb emitted(double length) const;
    // A distance drawn from exp(-sigma_t t) of a channel chosen by `u_channel` (the pdf the
    // mixture over the three channels), within `length`.
    FreeFlight sample_free_flight(double length, double u_channel, double u) const;

    // sigma_s p(cos_theta) summed over the media: the fraction scattered per unit length into
    // a unit solid angle at that angle from the direction of travel.
    Rgb scattered(double cos_theta) const;
    // The pdf of sample_phase's directions (the phase functions mixed by their mean scattering).
    double phase_pdf(double cos_theta) const;
    Vec3 sample_phase(Vec3 forward, double u_choice, double u1, double u2) const;

private:
    struct Component {
        Rgb scattering;
        PhaseFunction phase;
        double share = 0;  // of the phase sampling
    };
    bool present_ = false;
    Rgb extinction_, emission_;
    std::vector<Component> components_;
};

// The media of the scene's objects, by object index, and the rule of which one a segment
// lies in (above).
class Interiors {
public:
    Interiors() = default;
    // Refuses fade and media on objects without an inside (triangles, meshes, discs,
    // polygons, patches) and on parts of solids with an interior of their own.
    Interiors(const SceneDescription& scene, double to_internal);

    bool any() const { return any_; }
    // Whether some medium scatters or emits (only the path integrator renders that).
    bool participating() const { return participating_; }
    const InteriorMedium& medium(int object) const { return media_[size_t(object)]; }

    // The medium of a segment along `direction` that started in `start` (-1: none known) and
    // ends at `hit` (if `found`): an object index or -1.
    int segment_medium(int start, Vec3 direction, bool found, const SurfaceHit& hit) const;
    // The medium a path is in after turning at `hit` from `direction` to `wi`, given the one it
    // came through.
    int medium_after(int segment, Vec3 direction, const SurfaceHit& hit, Vec3 wi) const;

private:
    std::vector<InteriorMedium> media_;
    bool any_ = false, participating_ = false;
};

}  // namespace rayset::tracer
