#include "tracer/render/interior_media.h"

#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "core/error.h"
#include "tracer/render/render_scene.h"

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

bool interior_fills(const InteriorRef& interior) {
    return interior && (interior->fade_distance != 0 || !interior->media.empty());
}

// Shapes POV-Ray gives no inside (a mesh's inside_vector aside): a medium there has no extent.
bool has_inside(const Shape& shape) {
    return !(std::holds_alternative<TriangleShape>(shape) ||
             std::holds_alternative<SmoothTriangleShape>(shape) ||
             std::holds_alternative<MeshShape>(shape) ||
             std::holds_alternative<MeshFileShape>(shape) ||
             std::holds_alternative<DiscShape>(shape) ||
             std::holds_alternative<PolygonShape>(shape) ||
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

InteriorMedium::InteriorMedium(const Interior& interior, double to_internal,
                               const ColourDecoding& decoding) {
    if (interior.fade_distance > 0) {
        const Rgb& c = interior.fade_colour;
        if (max_component(c) > 1 || std::min({c.red, c.green, c.blue}) < 0)
            refuse("a fade_color outside 0..1 (it would amplify light)", interior.location);
        auto absorption = [&](double channel) {
            return fade_absorption(channel, interior.fade_distance, interior.fade_power);
        };
        extinction_ = {absorption(c.red), absorption(c.green), absorption(c.blue)};
        present_ = true;
    } else if (interior.fade_distance < 0) {
        refuse("a negative fade_distance", interior.location);
    }
    Rgb total_scattering;
    for (const MediaRef& media : interior.media) {
        const Media& m = *media;
        if (!m.densities.empty()) refuse("media density", m.location);
        if (std::min({m.absorption.red, m.absorption.green, m.absorption.blue,
                      m.scattering.red, m.scattering.green, m.scattering.blue}) < 0)
            refuse("media of negative absorption or scattering", m.location);
        extinction_ += m.absorption;
        emission_ += to_internal * decoding(m.emission);
        if (m.scattering_type > 0 && !is_black(m.scattering)) {
            extinction_ += m.extinction * m.scattering;
            components_.push_back({m.scattering, PhaseFunction(m.scattering_type, m.eccentricity)});
            total_scattering += m.scattering;
        }
        present_ = true;
    }
    for (Component& c : components_) c.share = average(c.scattering) / average(total_scattering);
}

Rgb InteriorMedium::transmittance(double length) const {
    if (std::isinf(length))
        return {extinction_.red > 0 ? 0 : 1.0, extinction_.green > 0 ? 0 : 1.0,
                extinction_.blue > 0 ? 0 : 1.0};
    return per_channel(-length * extinction_, [](double x) { return std::exp(x); });
}

Rgb InteriorMedium::emitted(double length) const {
    auto channel = [&](double emission, double sigma) {
        if (emission == 0) return 0.0;
        if (sigma <= 0) return emission * length;
        return emission * -std::expm1(-sigma * length) / sigma;
    };
    return {channel(emission_.red, extinction_.red), channel(emission_.green, extinction_.green),
            channel(emission_.blue, extinction_.blue)};
}

FreeFlight InteriorMedium::sample_free_flight(double length, double u_channel, double u) const {
    FreeFlight flight;
    if (!scatters()) {
        flight.t = length;
        flight.weight = transmittance(length);
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
        flight.weight = (1 / pdf) * transmittance(t);
        return flight;
    }
    const Rgb through = transmittance(length);
    const double survival = average(through);
    flight.t = length;
    flight.weight = survival > 0 ? (1 / survival) * through : Rgb{};
    return flight;
}

Rgb InteriorMedium::scattered(double cos_theta) const {
    Rgb sum;
    for (const Component& c : components_) sum += c.phase.eval(cos_theta) * c.scattering;
    return sum;
}

double InteriorMedium::phase_pdf(double cos_theta) const {
    double pdf = 0;
    for (const Component& c : components_) pdf += c.share * c.phase.eval(cos_theta);
    return pdf;
}

Vec3 InteriorMedium::sample_phase(Vec3 forward, double u_choice, double u1, double u2) const {
    // One uniform picks the component, and its remainder picks the branch of its mixture.
    size_t i = 0;
    for (; i + 1 < components_.size() && u_choice >= components_[i].share; ++i)
        u_choice -= components_[i].share;
    u_choice = std::clamp(u_choice / components_[i].share, 0.0, 1.0 - 1e-12);
    return components_[i].phase.sample(forward, u_choice, u1, u2);
}

Interiors::Interiors(const SceneDescription& scene, double to_internal) {
    const ColourDecoding decoding(scene.global);
    media_.resize(scene.objects.size());
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const ObjectInstance& object = scene.objects[i];
        refuse_part_media(object, object.appearance.interior);
        if (!interior_fills(object.appearance.interior)) continue;
        const Interior& interior = *object.appearance.interior;
        if (!has_inside(object.shape))
            refuse(fmt::format("fade or media in a {}, which has no inside",
                               shape_keyword(object.shape)),
                   interior.location);
        media_[i] = InteriorMedium(interior, to_internal, decoding);
        any_ = any_ || media_[i].present();
        participating_ = participating_ || media_[i].participates();
    }
}

int Interiors::segment_medium(int start, Vec3 direction, bool found, const SurfaceHit& hit) const {
    if (start >= 0) return start;
    if (found && dot(direction, hit.normal) > 0 && media_[size_t(hit.object)].present())
        return hit.object;
    return -1;
}

int Interiors::medium_after(int segment, Vec3 direction, const SurfaceHit& hit, Vec3 wi) const {
    if (dot(wi, hit.normal) < 0) return media_[size_t(hit.object)].present() ? hit.object : -1;
    return dot(direction, hit.normal) < 0 ? segment : -1;
}

}  // namespace rayset::tracer
