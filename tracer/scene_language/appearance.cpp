// What the appearance description knows besides its fields: pattern names, block pattern
// lists, POV-Ray's built-in colour maps, and transforms of textures, interiors and media.
#include "tracer/scene_language/appearance.h"

#include <map>

namespace rayset::tracer {

const char* pattern_name(PatternKind kind) {
    switch (kind) {
        case PatternKind::plain: return "plain";
        case PatternKind::agate: return "agate";
        case PatternKind::aoi: return "aoi";
        case PatternKind::average: return "average";
        case PatternKind::boxed: return "boxed";
        case PatternKind::bozo: return "bozo";
        case PatternKind::brick: return "brick";
        case PatternKind::bumps: return "bumps";
        case PatternKind::cells: return "cells";
        case PatternKind::checker: return "checker";
        case PatternKind::crackle: return "crackle";
        case PatternKind::cubic: return "cubic";
        case PatternKind::cylindrical: return "cylindrical";
        case PatternKind::density_file: return "density_file";
        case PatternKind::dents: return "dents";
        case PatternKind::facets: return "facets";
        case PatternKind::function: return "function";
        case PatternKind::gradient: return "gradient";
        case PatternKind::granite: return "granite";
        case PatternKind::hexagon: return "hexagon";
        case PatternKind::image_pattern: return "image_pattern";
        case PatternKind::julia: return "julia";
        case PatternKind::leopard: return "leopard";
        case PatternKind::mandel: return "mandel";
        case PatternKind::marble: return "marble";
        case PatternKind::object: return "object";
        case PatternKind::onion: return "onion";
        case PatternKind::pavement: return "pavement";
        case PatternKind::pigment_pattern: return "pigment_pattern";
        case PatternKind::planar: return "planar";
        case PatternKind::quilted: return "quilted";
        case PatternKind::radial: return "radial";
        case PatternKind::ripples: return "ripples";
        case PatternKind::slope: return "slope";
        case PatternKind::spherical: return "spherical";
        case PatternKind::spiral1: return "spiral1";
        case PatternKind::spiral2: return "spiral2";
        case PatternKind::spotted: return "spotted";
        case PatternKind::square: return "square";
        case PatternKind::tiling: return "tiling";
        case PatternKind::triangular: return "triangular";
        case PatternKind::waves: return "waves";
        case PatternKind::wood: return "wood";
        case PatternKind::wrinkles: return "wrinkles";
        case PatternKind::image_map: return "image_map";
        case PatternKind::bump_map: return "bump_map";
        case PatternKind::material_map: return "material_map";
    }
    return "";
}

int list_size(PatternKind kind) {
    switch (kind) {
        case PatternKind::checker:
        case PatternKind::brick:
        case PatternKind::object: return 2;
        case PatternKind::hexagon: return 3;
        case PatternKind::square: return 4;
        case PatternKind::triangular:
        case PatternKind::cubic: return 6;
        default: return 0;
    }
}

namespace {

BlendMap colour_map(std::initializer_list<std::pair<double, Colour>> entries) {
    BlendMap map;
    for (const auto& [value, colour] : entries) {
        BlendMapEntry entry;
        entry.value = value;
        entry.colour = colour;
        map.entries.push_back(entry);
    }
    return map;
}

// POV-Ray 3.7's built-in maps, read back from POV-Ray itself: the value of a pattern with
// `frequency 1e-9 phase V` is V, so `function { pigment { PATTERN frequency 1e-9 phase V } }`
// samples the map at V (at 0.005 steps and then around each break). Lists were read the
// same way at points of known index.
std::map<PatternKind, BlendMap> make_builtin_maps() {
    const Colour black{0, 0, 0}, white{1, 1, 1}, red{1, 0, 0}, green{0, 1, 0}, blue{0, 0, 1};
    const Colour yellow{1, 1, 0}, cyan{0, 1, 1}, magenta{1, 0, 1};
    const Colour light_wood{0.666, 0.312, 0.2}, dark_wood{0.4, 0.1333, 0.066};
    const Colour marble_red{0.9, 0.08, 0.08};
    std::map<PatternKind, BlendMap> maps;
    maps[PatternKind::plain] = colour_map({{0, black}, {1, white}});
    maps[PatternKind::agate] = colour_map({{0, white},
                                           {0.5, {0.95, 0.75, 0.5}},
                                           {0.5, {0.9, 0.7, 0.5}},
                                           {0.6, {0.9, 0.7, 0.4}},
                                           {0.6, {1, 0.7, 0.4}},
                                           {1, {0.6, 0.3, 0}}});
    maps[PatternKind::bozo] = colour_map(
        {{0.4, white}, {0.4, green}, {0.6, green}, {0.6, blue}, {0.8, blue}, {0.8, red}});
    maps[PatternKind::marble] = colour_map({{0, {0.9, 0.8, 0.8}},
                                            {0.45, marble_red},
                                            {0.45, black},
                                            {0.55, black},
                                            {0.55, marble_red},
                                            {1, {0.9, 0.8, 0.8}}});
    maps[PatternKind::radial] =
        colour_map({{0, cyan}, {0.333, yellow}, {0.666, magenta}, {1, cyan}});
    maps[PatternKind::wood] =
        colour_map({{0.3, light_wood}, {0.3, dark_wood}, {0.7, dark_wood}, {0.7, light_wood}});
    maps[PatternKind::mandel] =
        colour_map({{0, black}, {0.001, cyan}, {0.012, yellow}, {0.015, magenta}, {0.1, cyan}});
    maps[PatternKind::julia] = maps[PatternKind::mandel];
    maps[PatternKind::checker] = colour_map({{0, blue}, {1, green}});
    maps[PatternKind::object] = maps[PatternKind::checker];
    maps[PatternKind::hexagon] = colour_map({{0, blue}, {1, green}, {2, red}});
    maps[PatternKind::brick] = colour_map({{0, {0.5, 0.5, 0.5}}, {1, {0.6, 0.15, 0.15}}});
    maps[PatternKind::square] = colour_map({{0, red}, {1, green}, {2, blue}, {3, yellow}});
    maps[PatternKind::triangular] =
        colour_map({{0, red}, {1, green}, {2, blue}, {3, yellow}, {4, cyan}, {5, magenta}});
    maps[PatternKind::cubic] = maps[PatternKind::triangular];
    return maps;
}

}  // namespace

const BlendMap& builtin_colour_map(PatternKind kind) {
    static const std::map<PatternKind, BlendMap> maps = make_builtin_maps();
    const auto found = maps.find(kind);
    return found != maps.end() ? found->second : maps.at(PatternKind::plain);
}

// ---------------------------------------------------------------- transforms

void transform_pattern(Pattern& pattern, const Matrix4& transform) {
    // Consecutive transforms are one: the last one written grows.
    if (!pattern.warps.empty() && pattern.warps.back().kind == Warp::Kind::transform) {
        pattern.warps.back().transform = transform * pattern.warps.back().transform;
        return;
    }
    Warp warp;
    warp.transform = transform;
    pattern.warps.push_back(warp);
}

void transform_pigment(Pigment& pigment, const Matrix4& transform) {
    transform_pattern(pigment.pattern.edit(), transform);
    pigment.map = transformed_map(pigment.map, transform);
}

void transform_normal(Normal& normal, const Matrix4& transform) {
    transform_pattern(normal.pattern.edit(), transform);
    normal.map = transformed_map(normal.map, transform);
}

void transform_texture(Texture& texture, const Matrix4& transform) {
    switch (texture.kind) {
        case Texture::Kind::plain:
            transform_pigment(texture.pigment, transform);
            if (texture.normal) {
                auto normal = std::make_shared<Normal>(*texture.normal);
                transform_normal(*normal, transform);
                texture.normal = normal;
            }
            break;
        case Texture::Kind::patterned:
            transform_pattern(texture.pattern.edit(), transform);
            texture.map = transformed_map(texture.map, transform);
            break;
        case Texture::Kind::layered:
            for (TextureRef& layer : texture.layers) {
                auto copy = std::make_shared<Texture>(*layer);
                transform_texture(*copy, transform);
                layer = copy;
            }
            break;
    }
}

void transform_media(Media& media, const Matrix4& transform) {
    for (DensityRef& density : media.densities) {
        auto copy = std::make_shared<Pigment>(*density.item);
        transform_pigment(*copy, transform);
        density.item = copy;
    }
}

void transform_interior(Interior& interior, const Matrix4& transform) {
    for (MediaRef& media : interior.media) {
        auto copy = std::make_shared<Media>(*media);
        transform_media(*copy, transform);
        media = copy;
    }
}

namespace {

// A texture whose look is the same everywhere (a plain one with a solid pigment and no
// bumps): transforms do not change it, so it need not be copied.
bool position_independent(const Texture& texture) {
    return texture.kind == Texture::Kind::plain &&
           texture.pigment.pattern->kind == PatternKind::plain &&
           (!texture.normal || texture.normal->pattern->kind == PatternKind::plain);
}

bool is_identity(const Matrix4& m) { return m.m == Matrix4{}.m; }

}  // namespace

void transform_appearance(ObjectAppearance& appearance, const Matrix4& transform) {
    if (is_identity(transform)) return;
    for (TextureRef* texture : {&appearance.texture, &appearance.interior_texture})
        if (*texture && !position_independent(**texture)) {
            auto copy = std::make_shared<Texture>(**texture);
            transform_texture(*copy, transform);
            *texture = copy;
        }
    if (appearance.interior && !appearance.interior->media.empty()) {
        auto copy = std::make_shared<Interior>(*appearance.interior);
        transform_interior(*copy, transform);
        appearance.interior = copy;
    }
}

BlendMapPointer transformed_map(const BlendMapPointer& map, const Matrix4& transform) {
    if (!map || map->kind == BlendMapKind::colour || map->kind == BlendMapKind::slope) return map;
    auto copy = std::make_shared<BlendMap>(*map);
    for (BlendMapEntry& entry : copy->entries) {
        if (entry.pigment) {
            auto pigment = std::make_shared<Pigment>(*entry.pigment);
            transform_pigment(*pigment, transform);
            entry.pigment = pigment;
        }
        if (entry.normal) {
            auto normal = std::make_shared<Normal>(*entry.normal);
            transform_normal(*normal, transform);
            entry.normal = normal;
        }
        if (entry.texture) {
            auto texture = std::make_shared<Texture>(*entry.texture);
            transform_texture(*texture, transform);
            entry.texture = texture;
        }
    }
    return copy;
}

}  // namespace rayset::tracer
