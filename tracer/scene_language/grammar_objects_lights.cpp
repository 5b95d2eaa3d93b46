// light_source (reference manual 3.4.4.1) and light_group (3.4.4.2). A light is an object
// node: its location and vectors stay in the node's coordinates and its transforms gather in
// the node, as for any object, until add_to_scene places it.
#include <algorithm>
#include <limits>

#include <fmt/format.h>

#include "tracer/scene_language/object_grammar.h"

namespace rayset::tracer {
namespace {

enum class LightType { point, spotlight, cylinder, shadowless };

// The last type keyword decides the type and resets the spot parameters to the type's
// defaults (checked against POV-Ray: `spotlight radius 3 cylinder` has a cylinder's radius).
void set_type(LightSource& light, LightType type) {
    light.spotlight = type == LightType::spotlight;
    light.cylinder = type == LightType::cylinder;
    light.shadowless = type == LightType::shadowless;
    const bool cylinder = type == LightType::cylinder;
    light.radius = cylinder ? 0.75 : 30;
    light.falloff = cylinder ? 1 : 45;
    light.tightness = 0;
}

void parse_light_photons(Parser& p, const Token& keyword, LightSource& light) {
    const Token open = p.expect_open(keyword);
    for (;;) {
        const Token token = p.peek();
        if (token.is(Symbol::rbrace)) break;
        p.next();
        if (token.is(Keyword::reflection))
            light.photons_reflection = p.parse_optional_bool();
        else if (token.is(Keyword::refraction))
            light.photons_refraction = p.parse_optional_bool();
        else if (token.is(Keyword::area_light))
            light.photons_area_light = p.parse_optional_bool();
        else
            p.fail_identifier(
                token, fmt::format("reflection, refraction, area_light or '}}' to close 'photons' "
                                   "opened at {}",
                                   p.location_of(open).str()));
    }
    p.expect_close(keyword, open);
}

// looks_like { OBJECT|OBJECT_ID [modifiers] }: POV-Ray moves the object to where the light is when
// looks_like is read, then applies the block's modifiers (checked against POV-Ray's renders).
// projected_through { OBJECT [modifiers] } stays where it is written.
void parse_light_object(Parser& p, const Token& keyword, ObjectNode& node) {
    const Token open = p.expect_open(keyword);
    std::shared_ptr<ObjectNode> object;
    if (ObjectRef declared; p.take_declared(declared)) {
        object = std::make_shared<ObjectNode>(*declared);
    } else if (starts_object(p, p.peek())) {
        object = std::make_shared<ObjectNode>(*parse_object(p));
    } else {
        p.fail_identifier(
            p.peek(), fmt::format("an object or an object identifier in '{}'", p.word(keyword)));
    }
    if (keyword.is(Keyword::looks_like))
        transform_node(*object, translation(node.transform.point(node.light.position)), true);
    parse_object_modifiers(p, *object, keyword, open);
    (keyword.is(Keyword::looks_like) ? node.looks_like : node.projected_through) = object;
}

void parse_area_light(Parser& p, LightSource& light) {
    light.area_light = true;
    light.axis1 = p.parse_vector();
    p.accept_comma();
    light.axis2 = p.parse_vector();
    p.accept_comma();
    light.size1 = p.parse_int("as the first area_light size", 1);
    p.accept_comma();
    light.size2 = p.parse_int("as the second area_light size", 1);
}

// Spot parameters need a spotlight or cylinder type before them, point_at also allows
// parallel: POV-Ray refuses them on a point light.
void check_spot_item(Parser& p, const Token& token, const LightSource& light) {
    const bool spot = light.spotlight || light.cylinder;
    if (spot || (token.is(Keyword::point_at) && light.parallel)) return;
    p.fail(
        token,
        fmt::format("'{}' cannot be used with a {} light (write spotlight or cylinder{} before it)",
                    p.word(token), light.shadowless ? "shadowless" : "point",
                    token.is(Keyword::point_at) ? ", or parallel," : ""));
}

// The light modifiers that set one value: a float, or a flag (bare, or `KEYWORD [BOOL]`).
struct FloatItem {
    Keyword keyword;
    double LightSource::*value;
    bool spot_only;  // needs a spotlight or cylinder type before it
};
const FloatItem kFloatItems[] = {
    {Keyword::radius, &LightSource::radius, true},
    {Keyword::falloff, &LightSource::falloff, true},
    {Keyword::tightness, &LightSource::tightness, true},
    {Keyword::fade_distance, &LightSource::fade_distance, false},
    {Keyword::fade_power, &LightSource::fade_power, false},
};
struct FlagItem {
    Keyword keyword;
    bool LightSource::*flag;
    bool takes_bool;  // POV-Ray takes no value after jitter, circular, orient, parallel
};
const FlagItem kFlagItems[] = {
    {Keyword::parallel, &LightSource::parallel, false},
    {Keyword::jitter, &LightSource::jitter, false},
    {Keyword::circular, &LightSource::circular, false},
    {Keyword::orient, &LightSource::orient, false},
    {Keyword::area_illumination, &LightSource::area_illumination, true},
    {Keyword::media_interaction, &LightSource::media_interaction, true},
    {Keyword::media_attenuation, &LightSource::media_attenuation, true},
};

bool parse_light_value(Parser& p, LightSource& light, const Token& token, Keyword keyword) {
    for (const FloatItem& item : kFloatItems)
        if (item.keyword == keyword) {
            if (item.spot_only) check_spot_item(p, token, light);
            p.next();
            light.*item.value = p.parse_float(fmt::format("after '{}'", p.word(token)));
            return true;
        }
    for (const FlagItem& item : kFlagItems)
        if (item.keyword == keyword) {
            p.next();
            light.*item.flag = item.takes_bool ? p.parse_optional_bool() : true;
            return true;
        }
    return false;
}

bool parse_light_modifier(Parser& p, ObjectNode& node) {
    LightSource& light = node.light;
    const Token token = p.peek();
    Keyword keyword;
    if (!keyword_of(token, keyword)) return false;
    if (parse_light_value(p, light, token, keyword)) return true;
    switch (keyword) {
        case Keyword::spotlight:
        case Keyword::cylinder:
        case Keyword::shadowless:
            p.next();
            set_type(light, keyword == Keyword::spotlight  ? LightType::spotlight
                            : keyword == Keyword::cylinder ? LightType::cylinder
                                                           : LightType::shadowless);
            return true;
        case Keyword::point_at:
            check_spot_item(p, token, light);
            p.next();
            light.point_at = p.parse_vector();
            return true;
        case Keyword::area_light:
            p.next();
            parse_area_light(p, light);
            return true;
        case Keyword::adaptive:  // POV-Ray takes a negative value as 0
            p.next();
            light.adaptive =
                std::max(0, p.parse_int("after 'adaptive'", std::numeric_limits<int>::min()));
            return true;
        case Keyword::photons:
            p.next();
            parse_light_photons(p, token, light);
            return true;
        case Keyword::looks_like:
        case Keyword::projected_through:
            p.next();
            parse_light_object(p, token, node);
            return true;
        default: return false;
    }
}

// POV-Ray's corrections of an oriented area light at the end of its block, with its warnings
// (checked with povray): orient makes it circular and takes the first axis's length for both.
void correct_orient(Parser& p, const Token& keyword, LightSource& light) {
    if (!light.area_light || !light.orient) return;
    if (!light.circular) {
        p.warn(keyword,
               "orient can only be used with circular area lights: this one is now circular");
        light.circular = true;
    }
    const double first = length(light.axis1), second = length(light.axis2);
    if (first != second && second > 0) {
        p.warn(keyword,
               "with orient, the two axes of an area light must be of equal length: only the "
               "first axis's length is used");
        light.axis2 = (first / second) * light.axis2;
    }
    if (light.size1 != light.size2)
        p.warn(keyword, "with orient, the two sample sizes of an area light should be equal");
}

}  // namespace

// light_source { LIGHT_ID transforms } | light_source { <location> [, colour] modifiers }:
// POV-Ray takes nothing but transforms after an identifier, and no colour after the first
// (a light without one is black).
ObjectRef parse_light_source(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    const Token first = p.peek();
    if (ObjectRef declared; p.take_declared(declared)) {
        if (declared->kind != ObjectNode::Kind::light)
            p.fail(first, "wrong type: '" + p.word(first) +
                              "' is an object, expected a light_source identifier");
        auto node = std::make_shared<ObjectNode>(*declared);
        while (!p.peek_is(Symbol::rbrace))
            if (!parse_node_transform(p, *node))
                p.fail_identifier(
                    p.peek(),
                    fmt::format("a transform or '}}' to close 'light_source' opened at {} "
                                "(a declared light takes no other modifier)",
                                p.location_of(open).str()));
        p.expect_close(keyword, open);
        return node;
    }
    auto node = new_node(p, keyword, ObjectNode::Kind::light);
    node->bounds.known = node->bounds.infinite = true;  // POV-Ray's box of a light
    LightSource& light = node->light;
    light.location = node->location;
    light.position = p.parse_vector();
    p.accept_comma();
    light.colour = p.starts_colour(p.peek()) ? p.parse_colour().rgb() : Rgb{0, 0, 0};
    for (;;) {
        if (p.peek_is(Symbol::rbrace)) break;
        if (!parse_light_modifier(p, *node) && !parse_node_transform(p, *node))
            p.fail_identifier(
                p.peek(),
                fmt::format("a light_source modifier or '}}' to close 'light_source' opened at {}",
                            p.location_of(open).str()));
    }
    p.expect_close(keyword, open);
    correct_orient(p, keyword, light);
    return node;
}

// light_group { objects, lights and their identifiers, then transforms and global_lights }.
ObjectRef parse_light_group(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    auto node = new_node(p, keyword, ObjectNode::Kind::light_group);
    node->shape = CsgShape{};
    // Unlike CSG, a light group takes bare object and light identifiers (povray:
    // light_group { L1 }).
    for (;;) {
        if (starts_object(p, p.peek())) {
            node->children.push_back(parse_object(p));
        } else if (ObjectRef declared; p.take_declared(declared)) {
            node->children.push_back(declared);
        } else {
            break;
        }
    }
    compute_csg_bounds(*node);
    for (;;) {
        const Token token = p.peek();
        if (token.is(Symbol::rbrace)) break;
        if (parse_node_transform(p, *node)) continue;
        if (token.is(Keyword::global_lights)) {
            p.next();
            node->global_lights = p.parse_optional_bool();
            continue;
        }
        if (starts_object(p, token))
            p.fail(
                token,
                fmt::format(
                    "an object after the modifiers of 'light_group' opened at {} (its objects and "
                    "lights come first)",
                    p.location_of(open).str()));
        p.fail_identifier(
            token,
            fmt::format("a transform, global_lights or '}}' to close 'light_group' opened at {}",
                        p.location_of(open).str()));
    }
    p.expect_close(keyword, open);
    return node;
}

}  // namespace rayset::tracer
