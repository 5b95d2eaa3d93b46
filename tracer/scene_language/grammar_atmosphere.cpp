// The atmosphere: fog, rainbow and sky_sphere (statements and identifiers), with POV-Ray's
// defaults and checks. Several fogs and rainbows add up; a sky_sphere replaces the one before.
#include <cmath>

#include <fmt/format.h>

#include "tracer/scene_language/grammar.h"

namespace rayset::tracer {
namespace {

// The fog's transforms turn its up vector as they come (an up written after a rotate is not
// rotated; translations leave it alone) and all of them place the turbulence. Checked against
// POV-Ray 3.7 renders of a ground fog.
bool parse_fog_transform(Parser& p, Fog& fog) {
    Matrix4 step;
    if (!p.parse_transform_item(step)) return false;
    fog.up = step.vector(fog.up);
    fog.transform = step * fog.transform;
    return true;
}

// fog_type, distance, the turbulence keys, fog_offset, fog_alt, up (`token` just taken); false
// for anything else.
bool parse_fog_key(Parser& p, const Token& token, Fog& fog) {
    const std::string after = fmt::format("after '{}'", p.word(token));
    if (token.is(Keyword::fog_type)) {
        // As POV-Ray 3.7 renders it: 2 (after truncation) is ground fog, any other value constant.
        fog.fog_type = std::trunc(p.parse_float(after)) == 2 ? 2 : 1;
    } else if (token.is(Keyword::distance)) {
        fog.distance = p.parse_float(after);
    } else if (token.is(Keyword::turbulence)) {
        fog.turbulence = p.parse_vector();
    } else if (token.is(Keyword::octaves)) {
        fog.octaves = p.parse_int(after, 1);
    } else if (token.is(Keyword::omega)) {
        fog.omega = p.parse_float(after);
    } else if (token.is(Keyword::lambda)) {
        fog.lambda = p.parse_float(after);
    } else if (token.is(Keyword::turb_depth)) {
        fog.turb_depth = p.parse_float(after);
    } else if (token.is(Keyword::fog_offset)) {
        fog.fog_offset = p.parse_float(after);
    } else if (token.is(Keyword::fog_alt)) {
        fog.fog_alt = p.parse_float(after);
    } else if (token.is(Keyword::up)) {
        fog.up = p.parse_vector();
    } else {
        return false;
    }
    return true;
}

// Rainbow keys (`token` just taken); false for anything else.
bool parse_rainbow_key(Parser& p, const Token& token, Rainbow& rainbow) {
    const std::string after = fmt::format("after '{}'", p.word(token));
    if (token.is(Keyword::direction))
        rainbow.direction = p.parse_vector();
    else if (token.is(Keyword::angle))
        rainbow.angle = p.parse_float(after);
    else if (token.is(Keyword::width))
        rainbow.width = p.parse_float(after);
    else if (token.is(Keyword::distance))
        rainbow.distance = p.parse_float(after);
    else if (token.is(Keyword::jitter))
        rainbow.jitter = p.parse_float(after);
    else if (token.is(Keyword::up))
        rainbow.up = p.parse_vector();
    else if (token.is(Keyword::arc_angle))
        rainbow.arc_angle = p.parse_float(after);
    else if (token.is(Keyword::falloff_angle))
        rainbow.falloff_angle = p.parse_float(after);
    else if (token.is(Keyword::color_map) || token.is(Keyword::colour_map))
        rainbow.colour_map = parse_colour_map(p, token);
    else
        return false;
    return true;
}

// POV-Ray's checks once the block is read.
void check_rainbow(Parser& p, const Token& keyword, const Rainbow& rainbow) {
    if (length(rainbow.direction) == 0)
        p.fail(keyword, "the rainbow's direction is zero (or not given)");
    if (length(rainbow.up) == 0) p.fail(keyword, "the rainbow's up vector is zero");
    if (length(cross(rainbow.up, rainbow.direction)) == 0)
        p.fail(keyword, "the rainbow's up and direction vectors are parallel");
    if (!(rainbow.arc_angle >= 0 && rainbow.arc_angle <= 360))
        p.fail(keyword, fmt::format("the rainbow's arc_angle must be in [0, 360] degrees, found {}",
                                    rainbow.arc_angle));
    if (!(rainbow.falloff_angle >= 0 && rainbow.falloff_angle <= 360))
        p.fail(keyword, fmt::format("the rainbow's falloff_angle must be in [0, 360] degrees, "
                                    "found {}",
                                    rainbow.falloff_angle));
    if (rainbow.falloff_angle > rainbow.arc_angle)
        p.fail(keyword, fmt::format("the rainbow's falloff_angle {} is larger than its arc_angle "
                                    "{}",
                                    rainbow.falloff_angle, rainbow.arc_angle));
}

}  // namespace

FogRef parse_fog(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    auto fog = std::make_shared<Fog>();
    if (FogRef declared; p.take_declared(declared)) {
        *fog = *declared;
    }
    fog->location = p.location_of(keyword);
    for (;;) {
        const Token token = p.peek();
        if (token.is(Symbol::rbrace)) break;
        if (parse_fog_transform(p, *fog)) continue;
        if (p.starts_colour(token)) {
            fog->colour = p.parse_colour();
            continue;
        }
        p.next();
        if (!parse_fog_key(p, token, *fog))
            p.fail_identifier(token, fmt::format("a fog keyword, a colour or '}}' to close 'fog' "
                                                 "opened at {}",
                                                 p.location_of(open).str()));
    }
    p.expect_close(keyword, open);
    // POV-Ray measures heights along the unit up vector (`up 2*y` renders as `up y`).
    if (length(fog->up) > 0) fog->up = normalized(fog->up);
    return fog;
}

RainbowRef parse_rainbow(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    auto rainbow = std::make_shared<Rainbow>();
    if (RainbowRef declared; p.take_declared(declared)) {
        *rainbow = *declared;
    }
    rainbow->location = p.location_of(keyword);
    while (!p.peek_is(Symbol::rbrace)) {
        const Token token = p.next();
        if (!parse_rainbow_key(p, token, *rainbow))
            p.fail_identifier(token, fmt::format("a rainbow keyword or '}}' to close 'rainbow' "
                                                 "opened at {}",
                                                 p.location_of(open).str()));
    }
    p.expect_close(keyword, open);
    check_rainbow(p, keyword, *rainbow);
    return rainbow;
}

// The transforms apply to the whole sky wherever they are written (checked against POV-Ray 3.7
// renders); pigments add layers, the last on top.
SkySphereRef parse_sky_sphere(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    auto sky = std::make_shared<SkySphere>();
    if (SkySphereRef declared; p.take_declared(declared)) {
        *sky = *declared;
    }
    sky->location = p.location_of(keyword);
    for (;;) {
        const Token token = p.peek();
        if (token.is(Symbol::rbrace)) break;
        if (p.parse_transform_item(sky->transform)) continue;
        p.next();
        if (token.is(Keyword::pigment))
            sky->pigments.push_back(parse_pigment(p, token));
        else if (token.is(Keyword::emission))
            sky->emission = p.parse_colour().rgb();
        else
            p.fail_identifier(token, fmt::format("pigment, emission, a transform or '}}' to close "
                                                 "'sky_sphere' opened at {}",
                                                 p.location_of(open).str()));
    }
    p.expect_close(keyword, open);
    if (sky->pigments.empty()) p.fail(keyword, "the sky_sphere has no pigment");
    return sky;
}

void parse_atmospheric_media(Parser& p, const Token& keyword) {
    AtmosphericMedia media;
    media.media = parse_media(p, keyword);
    media.location = p.location_of(keyword);
    p.scene().atmosphere.media.push_back(media);
}

}  // namespace rayset::tracer
