#include "tracer/render/sky.h"

#include <fmt/format.h>

#include "core/error.h"
#include "tracer/scene_language/grammar.h"

namespace rayset::tracer {

namespace {

[[noreturn]] void refuse_pigment(const Pigment& pigment, const SkySphere& sky) {
    const SourceLocation& at =
        pigment.pattern->location.file.empty() ? sky.location : pigment.pattern->location;
    throw Error(fmt::format("not supported: pigment pattern '{}' in sky_sphere at {}",
                            pattern_name(pigment.pattern->kind), at.str()));
}

}  // namespace

Sky::Sky(const SceneDescription& scene, double to_internal)
    : decoding_(scene.global),
      background_(to_internal * decoding_(scene.background.rgb())),
      background_spectrum_(background_),
      sky_(scene.atmosphere.sky_sphere),
      to_internal_(to_internal) {
    if (!sky_) return;
    world_to_sky_ = sky_->transform.inverse();
    for (const PigmentRef& pigment : sky_->pigments)
        if (!pigment_is_evaluable(*pigment)) refuse_pigment(*pigment, *sky_);
}

Rgb Sky::radiance(Vec3 direction) const {
    if (!sky_) return background_;
    const Vec3 at = world_to_sky_.vector(direction);
    // From the top layer down: what each shows, times what the layers above let through.
    Rgb sum{}, through{1, 1, 1};
    for (auto layer = sky_->pigments.rbegin(); layer != sky_->pigments.rend(); ++layer) {
        Colour c;
        if (!evaluate_pigment(**layer, at, c)) refuse_pigment(**layer, *sky_);
        const Rgb colour = decoding_(c.rgb());
        const double opacity = 1 - c.filter - c.transmit;
        sum += (to_internal_ * opacity) * (through * sky_->emission * colour);
        through = through * (c.filter * colour + Rgb{c.transmit, c.transmit, c.transmit});
    }
    return sum + through * background_;
}

}  // namespace rayset::tracer
