#include "tracer/render/interior_media.h"

#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "core/error.h"
#include "tracer/render/render_scene.h"
#include "tracer/scene_language/grammar.h"

namespace rayset::tracer {
namespace {

[[noreturn]] void refuse(const std::string& feature, const SourceLocation& where) {
    throw Error(fmt::format("not supported: {} at {}", feature, where.str()));
}

Rgb per_channel(Rgb a, double (*f)(double)) { return {f(a.red), f(a.green), f(a.blue)}; }

// The Beer-Lambert absorption of POV-Ray's fade (interior_media.h) in one channel.
double fade_absorption(double fade_colour, double fade_distance, double fade_power) {
    if (fade_power >= 1000) return (1 - fade_colour) / fade_distance;
    return -std::log((1 + fade_colour) / 2) / fade_distance;
}

// The largest value of a density's colour, channel by channel, anywhere: its colour, or the
// largest entry of its map (patterns blend between entries), densities of a density_map each
// bounded the same way.
Rgb largest_colour(const Pigment& pigment) {
    auto larger = [](Rgb a, Rgb b) {
        return Rgb{std::max(a.red, b.red), std::max(a.green, b.green), std::max(a.blue, b.blue)};
    };
    if (pigment.pattern->kind == PatternKind::plain) return pigment.colour.rgb();
    const BlendMap& map = pigment.map ? *pigment.map : builtin_colour_map(pigment.pattern->kind);
    Rgb largest;
    for (const BlendMapEntry& entry : map.entries)
        largest =
            larger(largest, entry.pigment ? largest_colour(*entry.pigment) : entry.colour.rgb());
    return largest;
}

bool interior_fills(const InteriorRef& interior) {
    return interior && (interior->fade_distance != 0 || !interior->media.empty());
}

// Shapes POV-Ray gives no inside (a mesh's inside_vector aside): a medium there has no extent.
bool has_inside(const Shape& shape) {
    return !(
        std::holds_alternative<TriangleShape>(shape) ||
        std::holds_alternative<SmoothTriangleShape>(shape) ||
        std::holds_alternative<MeshShape>(shape) || std::holds_alternative<MeshFileShape>(shape) ||
        std::holds_alternative<DiscShape>(shape) || std::holds_alternative<PolygonShape>(shape) ||
        std::holds_alternative<BicubicPatchShape>(shape));
}

// A solid's parts show their own interiors nowhere but on their surfaces; a medium of a part
// would fill only that part, which the rule of segments does not know.
void refuse_part_media(const ObjectInstance& object, const InteriorRef& whole) {
    const auto* csg = std::get_if<CsgShape>(&object.shape);
    if (!csg) return;
    for (const ObjectInstance& part : csg->children) {
        if (part.appearance.interior != whole && interior_fills(part.appearance.interior))
            refuse("fade or media in an interior of a part of a CSG object",
                   part.appearance.interior->location);
        refuse_part_media(part, whole);
    }
}

}  // namespace

InteriorMedium::InteriorMedium(const InteriorRef& interior_ref, double to_internal,
                               const ColourDecoding& decoding)
    : keep_(interior_ref) {
    const Interior& interior = *interior_ref;
    if (interior.fade_distance > 0) {
        const Rgb& c = interior.fade_colour;
        if (max_component(c) > 1 || std::min({c.red, c.green, c.blue}) < 0)
            refuse("a fade_color outside 0..1 (it would amplify light)", interior.location);
        auto absorption = [&](double channel) {
            return fade_absorption(channel, interior.fade_distance, interior.fade_power);
        };
        Part fade;
        fade.extinction = {absorption(c.red), absorption(c.green), absorption(c.blue)};
        parts_.push_back(fade);
    } else if (interior.fade_distance < 0) {
        refuse("a negative fade_distance", interior.location);
    }
    for (const MediaRef& media : interior.media)
        parts_.push_back(part_of(*media, to_internal, decoding));
    sum_parts();
}

InteriorMedium::InteriorMedium(const std::vector<AtmosphericMedia>& media, double to_internal,
                               const ColourDecoding& decoding) {
    for (const AtmosphericMedia& m : media) {
        if (!m.media->densities.empty()) refuse("density in atmospheric media", m.media->location);
        parts_.push_back(part_of(*m.media, to_internal, decoding));
    }
    sum_parts();
    const Rgb e = emission_, s = extinction_;
    if ((e.red > 0 && s.red <= 0) || (e.green > 0 && s.green <= 0) || (e.blue > 0 && s.blue <= 0))
        refuse("atmospheric media emitting without extinction (infinite radiance toward the sky)",
               media.front().location);
}

void InteriorMedium::sum_parts() {
    Rgb total_scattering;
    for (const Part& part : parts_) {
        total_scattering += part.scattering;
        uniform_ = uniform_ && part.densities.empty();
        extinction_ += part.extinction;
        emission_ += part.emission;
        majorant_ += max_component(part.extinction * part.density_bound);
        scatters_ = scatters_ || !is_black(part.scattering);
        emits_ = emits_ || !is_black(part.emission);
    }
    for (Part& part : parts_)
        part.phase_share = scatters_ ? average(part.scattering) / average(total_scattering) : 0;
}

InteriorMedium::Part InteriorMedium::part_of(const Media& m, double to_internal,
                                             const ColourDecoding& decoding) {
    if (std::min({m.absorption.red, m.absorption.green, m.absorption.blue, m.scattering.red,
                  m.scattering.green, m.scattering.blue}) < 0)
        refuse("media of negative absorption or scattering", m.location);
    Part part;
    part.extinction = m.absorption;
    part.emission = to_internal * decoding(m.emission);
    if (m.scattering_type > 0 && !is_black(m.scattering)) {
        part.extinction += m.extinction * m.scattering;
        part.scattering = m.scattering;
        part.phase = PhaseFunction(m.scattering_type, m.eccentricity);
    }
    for (const DensityRef& density : m.densities) {
        const Pigment& pigment = *density.item;
        if (pigment.pattern->kind != PatternKind::plain && !pigment_is_evaluable(pigment))
            refuse(fmt::format("density pattern '{}'", pattern_name(pigment.pattern->kind)),
                   pigment.location);
        part.densities.push_back(&pigment);
        part.density_bound *= largest_colour(pigment);
    }
    return part;
}

Rgb InteriorMedium::Part::density(Vec3 point) const {
    Rgb product{1, 1, 1};
    for (const Pigment* pigment : densities) {
        Colour c;
        if (!evaluate_pigment(*pigment, point, c))
            throw Error(
                fmt::format("not supported: the density at {} (its value at ({}, {}, {}) "
                            "is not known)",
                            pigment->location.str(), point.x, point.y, point.z));
        product *= Rgb{std::max(0.0, c.red), std::max(0.0, c.green), std::max(0.0, c.blue)};
    }
    return product;
}

InteriorMedium::Local InteriorMedium::at(Vec3 point) const {
    Local local;
    for (const Part& part : parts_) {
        const Rgb d = part.densities.empty() ? Rgb{1, 1, 1} : part.density(point);
        local.extinction += d * part.extinction;
        local.scattering += d * part.scattering;
        local.emission += d * part.emission;
    }
    return local;
}

Rgb InteriorMedium::uniform_transmittance(double length) const {
    if (std::isinf(length))
        return {extinction_.red > 0 ? 0 : 1.0, extinction_.green > 0 ? 0 : 1.0,
                extinction_.blue > 0 ? 0 : 1.0};
    return per_channel(-length * extinction_, [](double x) { return std::exp(x); });
}

Rgb InteriorMedium::uniform_emitted(double length) const {
    auto channel = [&](double emission, double sigma) {
        if (emission == 0) return 0.0;
        if (sigma <= 0) return emission * length;
        return emission * -std::expm1(-sigma * length) / sigma;
    };
    return {channel(emission_.red, extinction_.red), channel(emission_.green, extinction_.green),
            channel(emission_.blue, extinction_.blue)};
}

Rgb InteriorMedium::transmittance(Vec3 origin, Vec3 direction, double length, Pcg32& rng) const {
    if (uniform_) return uniform_transmittance(length);
    if (!(majorant_ > 0)) return {1, 1, 1};
    Rgb through{1, 1, 1};
    for (double t = 0;;) {
        t -= std::log1p(-rng.uniform()) / majorant_;
        if (t >= length) return through;
        const Rgb extinction = at(origin + t * direction).extinction;
        through *= (1 / majorant_) * (Rgb{majorant_, majorant_, majorant_} - extinction);
        if (is_black(through)) return {};
    }
}

FreeFlight InteriorMedium::fly(Vec3 origin, Vec3 direction, double length, Pcg32& rng) const {
    if (uniform_) return fly_uniform(length, rng);
    FreeFlight flight;
    flight.weight = {1, 1, 1};
    // Emission is collected at tentative collisions: at least a few along the segment.
    const double rate = std::max(majorant_, emits_ && std::isfinite(length) ? 8 / length : 0.0);
    if (!(rate > 0)) return flight;
    for (double t = 0;;) {
        t -= std::log1p(-rng.uniform()) / rate;
        if (t >= length) return flight;
        const Local local = at(origin + t * direction);
        flight.emitted += (1 / rate) * (flight.weight * local.emission);
        const Rgb null = Rgb{rate, rate, rate} - local.extinction;
        const double scatter = average(local.scattering), pass = average(null);
        if (!(scatter + pass > 0)) {
            flight.weight = {};  // absorbed everywhere here
            return flight;
        }
        const double p_scatter = scatter / (scatter + pass);
        if (rng.uniform() < p_scatter) {
            flight.scattered = true;
            flight.t = t;
            flight.weight = (1 / (rate * p_scatter)) * flight.weight;
            return flight;
        }
        flight.weight *= (1 / (rate * (1 - p_scatter))) * null;
    }
}

FreeFlight InteriorMedium::fly_uniform(double length, Pcg32& rng) const {
    FreeFlight flight;
    flight.emitted = uniform_emitted(length);
    const double u_channel = rng.uniform_float(), u = rng.uniform_float();
    if (!scatters_) {
        flight.t = length;
        flight.weight = uniform_transmittance(length);
        return flight;
    }
    const double sigma[3] = {extinction_.red, extinction_.green, extinction_.blue};
    const double chosen = sigma[std::min(2, int(3 * u_channel))];
    const double t =
        chosen > 0 ? -std::log1p(-u) / chosen : std::numeric_limits<double>::infinity();
    if (t < length) {
        double pdf = 0;
        for (double s : sigma) pdf += s * std::exp(-s * t) / 3;
        flight.scattered = true;
        flight.t = t;
        flight.weight = (1 / pdf) * uniform_transmittance(t);
        return flight;
    }
    const Rgb through = uniform_transmittance(length);
    const double survival = average(through);
    flight.t = length;
    flight.weight = survival > 0 ? (1 / survival) * through : Rgb{};
    return flight;
}

Rgb InteriorMedium::scattered(Vec3 point, double cos_theta) const {
    Rgb sum;
    for (const Part& part : parts_) {
        if (is_black(part.scattering)) continue;
        const Rgb d = part.densities.empty() ? Rgb{1, 1, 1} : part.density(point);
        sum += part.phase.eval(cos_theta) * (d * part.scattering);
    }
    return sum;
}

double InteriorMedium::phase_pdf(double cos_theta) const {
    double pdf = 0;
    for (const Part& part : parts_) pdf += part.phase_share * part.phase.eval(cos_theta);
    return pdf;
}

Vec3 InteriorMedium::sample_phase(Vec3 forward, double u_choice, double u1, double u2) const {
    // One uniform picks the part (the shares of those that scatter sum to 1), and its
    // remainder picks the branch of its phase function's mixture.
    size_t chosen = 0;
    for (size_t j = 0; j < parts_.size(); ++j) {
        const double share = parts_[j].phase_share;
        if (share <= 0) continue;
        chosen = j;
        if (u_choice < share) break;
        u_choice -= share;
    }
    u_choice = std::clamp(u_choice / parts_[chosen].phase_share, 0.0, 1.0 - 1e-12);
    return parts_[chosen].phase.sample(forward, u_choice, u1, u2);
}

Interiors::Interiors(const SceneDescription& scene, double to_internal) {
    const ColourDecoding decoding(scene.global);
    media_.resize(scene.objects.size());
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const ObjectInstance& object = scene.objects[i];
        hollow_.push_back(object.hollow);
        refuse_part_media(object, object.appearance.interior);
        if (!interior_fills(object.appearance.interior)) continue;
        const Interior& interior = *object.appearance.interior;
        if (!has_inside(object.shape))
            refuse(fmt::format("fade or media in a {}, which has no inside",
                               shape_keyword(object.shape)),
                   interior.location);
        if (!scene.atmosphere.media.empty())
            refuse("atmospheric media together with fade or media in objects", interior.location);
        media_[i] = InteriorMedium(object.appearance.interior, to_internal, decoding);
        any_ = any_ || media_[i].present();
        participating_ = participating_ || media_[i].participates();
    }
    if (scene.atmosphere.media.empty()) return;
    // Receivers take their light samples undimmed (receiver_irradiance.h): in an atmosphere
    // that would be wrong everywhere.
    if (!scene.receivers.empty())
        refuse("illuminance receivers in atmospheric media",
               scene.atmosphere.media.front().location);
    outside_ = int(media_.size());
    media_.emplace_back(scene.atmosphere.media, to_internal, decoding);
    any_ = true;
    participating_ = participating_ || media_.back().participates();
}

int Interiors::segment_medium(int start, Vec3 direction, bool found, const SurfaceHit& hit) const {
    if (start >= 0) return start;
    if (start == kNoMedium) return -1;
    if (found && dot(direction, hit.normal) > 0) {  // leaving the object it was in
        const size_t object = size_t(hit.object);
        if (media_[object].present()) return hit.object;
        return hollow_[object] ? outside_ : -1;
    }
    return outside_;
}

int Interiors::medium_after(int segment, Vec3 direction, const SurfaceHit& hit, Vec3 wi) const {
    if (dot(wi, hit.normal) < 0) {  // into the object
        const size_t object = size_t(hit.object);
        if (media_[object].present()) return hit.object;
        return hollow_[object] ? outside_ : kNoMedium;
    }
    return dot(direction, hit.normal) < 0 ? segment : -1;
}

}  // namespace rayset::tracer
