// Textures (reference 3.4.6): plain, patterned (texture_map, texture lists, tiles,
// material_map) and layered; the appearance modifiers of objects (texture, pigment, normal,
// finish, interior, interior_texture, material) with POV-Ray's rules for layering and
// inheritance; material { }; and #default (3.3.2.4). The error texts in quotes are POV-Ray's.
#include <fmt/format.h>

#include "tracer/scene_language/appearance_grammar.h"

namespace rayset::tracer {
namespace {

// `above` laid over `below`, as POV-Ray layers textures: only plain layers.
TextureRef layer(Parser& p, const Token& at, const TextureRef& below, const TextureRef& above) {
    if (above->kind == Texture::Kind::patterned)
        p.fail(at,
               "cannot layer a patterned texture over another (POV-Ray: \"Cannot layer a patterned "
               "texture "
               "over another\")");
    if (below->kind == Texture::Kind::patterned)
        p.fail(at,
               "cannot layer over a patterned texture (POV-Ray: \"Cannot layer over a patterned "
               "texture\")");
    auto layered = std::make_shared<Texture>();
    layered->kind = Texture::Kind::layered;
    layered->location = below->location;
    for (const TextureRef& part : {below, above}) {
        if (part->kind == Texture::Kind::layered)
            layered->layers.insert(layered->layers.end(), part->layers.begin(), part->layers.end());
        else
            layered->layers.push_back(part);
    }
    return layered;
}

// The layer that pigment, normal and finish statements modify: the top one (POV-Ray's, checked
// with POV-Ray 3.7: `texture { LAYERED pigment { ... } }` changes the last layer written).
Texture& top_layer(Parser& p, const Token& at, Texture& texture) {
    if (texture.kind == Texture::Kind::patterned)
        p.fail(
            at,
            fmt::format(
                "'{}' cannot modify a patterned texture (POV-Ray: \"Cannot layer over a patterned "
                "texture\")",
                p.word(at)));
    if (texture.kind == Texture::Kind::plain) return texture;
    auto top = std::make_shared<Texture>(*texture.layers.back());
    texture.layers.back() = top;
    return *top;
}

// pigment { }, normal { } or finish { } (keyword taken) modifying the plain texture's own.
void parse_texture_part(Parser& p, const Token& keyword, Texture& texture) {
    const Token open = p.expect_open(keyword);
    if (keyword.is(Keyword::pigment)) {
        parse_pigment_body(p, texture.pigment, PatternRole::pigment, keyword, open, Symbol::rbrace);
    } else if (keyword.is(Keyword::normal)) {
        auto normal = std::make_shared<Normal>(texture.normal ? *texture.normal : Normal{});
        parse_normal_body(p, *normal, keyword, open, Symbol::rbrace);
        texture.normal = normal;
    } else {
        parse_finish_body(p, texture.finish.edit(), keyword, open);
    }
    p.expect_close(keyword, open);
}

bool is_texture_part(const Token& token) {
    return token.is(Keyword::pigment) || token.is(Keyword::normal) || token.is(Keyword::finish);
}

// A pigment, normal or finish identifier written alone in a texture: it replaces that part.
bool parse_part_identifier(Parser& p, Texture& texture) {
    PigmentRef pigment;
    FinishRef finish;
    if (p.take_declared(pigment))
        texture.pigment = *pigment;
    else if (p.take_declared(texture.normal))
        return true;
    else if (p.take_declared(finish))
        texture.finish = *finish;
    else
        return false;
    return true;
}

// uv_mapping in a texture: its pattern, pigment and normal (every layer's) are looked up at
// the surface's <u, v, 0>.
void set_uv_mapping(Texture& texture) {
    texture.pattern.edit().uv_mapping = true;
    texture.pigment.pattern.edit().uv_mapping = true;
    if (texture.normal) {
        auto normal = std::make_shared<Normal>(*texture.normal);
        normal->pattern.edit().uv_mapping = true;
        texture.normal = normal;
    }
    for (TextureRef& layer : texture.layers) {
        auto copy = std::make_shared<Texture>(*layer);
        set_uv_mapping(*copy);
        layer = copy;
    }
}

// The rest of a plain or layered texture: part identifiers, parts, transforms, uv_mapping.
void parse_plain_texture_items(Parser& p, Texture& texture, const Token& keyword, const Token& open,
                               Symbol close) {
    bool uv_mapping = false;
    for (;;) {
        const Token token = p.peek();
        if (token.is(close)) break;
        Matrix4 transform;
        if (p.parse_transform_item(transform)) {
            // Only the parts written so far move (reference 3.4.6).
            transform_texture(texture, transform);
        } else if (is_texture_part(token)) {
            p.next();
            parse_texture_part(p, token, top_layer(p, token, texture));
        } else if (token.is(Keyword::uv_mapping)) {
            p.next();
            uv_mapping = true;
        } else if (!parse_part_identifier(p, top_layer(p, token, texture))) {
            p.fail_identifier(token, fmt::format("pigment, normal, finish, a transform or {}",
                                                 closing_purpose(p, keyword, open, close)));
        }
    }
    if (uv_mapping) set_uv_mapping(texture);
}

// The modifiers of a patterned texture: pattern modifiers, texture_map, transforms. After a
// patterned texture identifier only transforms (reference 3.4.6.5).
void parse_patterned_texture_items(Parser& p, Texture& texture, const Token& keyword,
                                   const Token& open, Symbol close, bool from_identifier) {
    Matrix4 entries_transform;
    for (;;) {
        const Token token = p.peek();
        if (token.is(close)) break;
        Matrix4 transform;
        if (p.parse_transform_item(transform)) {
            transform_pattern(texture.pattern.edit(), transform);
            entries_transform = transform * entries_transform;
        } else if (!from_identifier && token.is(Keyword::texture_map)) {
            p.next();
            texture.map = parse_map_modifier(p, token, BlendMapKind::texture, *texture.pattern);
        } else if (from_identifier ||
                   !parse_pattern_modifier(p, texture.pattern.edit(), PatternRole::texture)) {
            if (is_texture_part(token))
                p.fail(token,
                       fmt::format(
                           "a patterned texture takes no '{}': give it to the textures in its map "
                           "or list (POV-Ray's rule)",
                           p.word(token)));
            p.fail_identifier(
                token,
                fmt::format("{} or {}", from_identifier ? "a transform" : "a texture modifier",
                            closing_purpose(p, keyword, open, close)));
        }
    }
    texture.map = transformed_map(texture.map, entries_transform);
}

// tiles { TEXTURE... tile2 TEXTURE... }: POV-Ray's old checker of two (possibly layered)
// textures.
void parse_tiles(Parser& p, Texture& texture, const Token& tiles) {
    const Token open = p.expect_open(tiles);
    auto textures = std::make_shared<BlendMap>();
    textures->kind = BlendMapKind::texture;
    for (int tile = 0; tile < 2; ++tile) {
        if (tile == 1) p.expect(Keyword::tile2, "after the first tile's textures");
        TextureRef layers;
        while (p.peek_is(Keyword::texture)) {
            const Token keyword = p.next();
            const TextureRef t = parse_texture(p, keyword);
            layers = layers ? layer(p, keyword, layers, t) : t;
        }
        if (!layers)
            p.fail_expected(fmt::format("a texture for tile {} of 'tiles'", tile + 1), p.peek());
        BlendMapEntry entry;
        entry.value = tile;
        entry.texture = layers;
        textures->entries.push_back(entry);
    }
    p.expect_close(tiles, open);
    texture.kind = Texture::Kind::patterned;
    texture.pattern = Pattern{};
    texture.pattern.edit().kind = PatternKind::checker;
    texture.pattern.edit().location = p.location_of(tiles);
    texture.map = textures;
}

InteriorRef parse_interior_from(Parser& p, const Token& keyword, const InteriorRef& start) {
    const Token open = p.expect_open(keyword);
    auto interior = std::make_shared<Interior>(start ? *start : Interior{});
    InteriorRef declared;
    if (p.take_declared(declared)) *interior = *declared;
    interior->location = p.location_of(keyword);
    parse_interior_items(p, *interior, keyword, open);
    p.expect_close(keyword, open);
    return interior;
}

// pigment, normal or finish as an object modifier: they modify the object's top texture
// layer, or a copy of the default texture when it has none (reference 3.3.2.4).
void modify_object_texture(Parser& p, const Token& keyword, ObjectAppearance& appearance) {
    auto texture =
        std::make_shared<Texture>(appearance.texture ? *appearance.texture : default_texture(p));
    if (!appearance.texture) texture->location = p.location_of(keyword);
    parse_texture_part(p, keyword, top_layer(p, keyword, *texture));
    appearance.texture = texture;
}

// material { [ID] texture... interior_texture interior transforms }
MaterialRef parse_material_block(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    auto material = std::make_shared<TextureAndInterior>();
    MaterialRef declared;
    if (p.take_declared(declared)) *material = *declared;
    for (;;) {
        const Token token = p.peek();
        if (token.is(Symbol::rbrace)) break;
        Matrix4 transform;
        if (p.parse_transform_item(transform)) {
            // Only what the material holds so far moves (reference 3.4.5.5.3).
            ObjectAppearance held{material->texture, material->interior_texture,
                                  material->interior};
            transform_appearance(held, transform);
            *material = {held.texture, held.interior_texture, held.interior};
            continue;
        }
        p.next();
        if (token.is(Keyword::texture) || token.is(Keyword::interior_texture)) {
            TextureRef& slot =
                token.is(Keyword::texture) ? material->texture : material->interior_texture;
            const TextureRef t = parse_texture(p, token);
            slot = slot ? layer(p, token, slot, t) : t;
        } else if (token.is(Keyword::interior)) {
            material->interior = parse_interior_from(p, token, material->interior);
        } else {
            p.fail_identifier(token,
                              fmt::format("texture, interior_texture, interior, a transform or {}",
                                          closing_purpose(p, keyword, open)));
        }
    }
    p.expect_close(keyword, open);
    return material;
}

}  // namespace

TextureRef parse_texture_body(Parser& p, const Token& keyword, const Token& open, Symbol close) {
    auto texture = std::make_shared<Texture>(default_texture(p));
    texture->location = p.location_of(keyword);
    const bool uv_mapping = p.accept(Keyword::uv_mapping);  // texture { uv_mapping TEXTURE_BODY }
    TextureRef declared;
    const bool from_identifier = p.take_declared(declared);
    if (from_identifier) *texture = *declared;
    const Token first = p.peek();
    if (!from_identifier && is_pattern_type(p, first, PatternRole::texture)) {
        p.next();
        texture->kind = Texture::Kind::patterned;
        texture->pattern = Pattern{};
        const BlendMapPointer list =
            parse_pattern_type(p, first, texture->pattern.edit(), PatternRole::texture, nullptr);
        texture->map = list;
    } else if (!from_identifier && first.is(Keyword::tiles)) {
        p.next();
        parse_tiles(p, *texture, first);
    }
    if (texture->kind == Texture::Kind::patterned)
        parse_patterned_texture_items(p, *texture, keyword, open, close,
                                      from_identifier || first.is(Keyword::tiles));
    else
        parse_plain_texture_items(p, *texture, keyword, open, close);
    if (uv_mapping) set_uv_mapping(*texture);
    return texture;
}

TextureRef parse_texture(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    TextureRef texture = parse_texture_body(p, keyword, open, Symbol::rbrace);
    p.expect_close(keyword, open);
    return texture;
}

TextureRef layer_textures(Parser& p, const Token& at, const TextureRef& below,
                          const TextureRef& above) {
    return layer(p, at, below, above);
}

InteriorRef parse_interior(Parser& p, const Token& keyword) {
    return parse_interior_from(p, keyword, nullptr);
}

MaterialRef parse_material(Parser& p, const Token& keyword) {
    return parse_material_block(p, keyword);
}

bool parse_appearance_modifier(Parser& p, ObjectAppearance& appearance) {
    const Token keyword = p.peek();
    if (keyword.is(Keyword::texture) || keyword.is(Keyword::interior_texture)) {
        p.next();
        TextureRef& slot =
            keyword.is(Keyword::texture) ? appearance.texture : appearance.interior_texture;
        const TextureRef texture = parse_texture(p, keyword);
        slot = slot ? layer(p, keyword, slot, texture) : texture;
    } else if (is_texture_part(keyword)) {
        p.next();
        modify_object_texture(p, keyword, appearance);
    } else if (keyword.is(Keyword::interior)) {
        p.next();
        // An object's interior modifies the one it has (checked with POV-Ray 3.7: media add up).
        appearance.interior = parse_interior_from(p, keyword, appearance.interior);
    } else if (keyword.is(Keyword::material)) {
        p.next();
        // The material's texture is layered over the object's; its interior replaces the object's.
        const MaterialRef material = parse_material(p, keyword);
        if (material->texture)
            appearance.texture = appearance.texture
                                     ? layer(p, keyword, appearance.texture, material->texture)
                                     : material->texture;
        if (material->interior_texture)
            appearance.interior_texture =
                appearance.interior_texture
                    ? layer(p, keyword, appearance.interior_texture, material->interior_texture)
                    : material->interior_texture;
        if (material->interior) appearance.interior = material->interior;
    } else {
        return false;
    }
    return true;
}

void inherit_appearance(ObjectAppearance& inner, const ObjectAppearance& outer) {
    if (!inner.texture) inner.texture = outer.texture;
    if (!inner.interior_texture) inner.interior_texture = outer.interior_texture;
    if (!inner.interior) inner.interior = outer.interior;
}

ObjectAppearance scene_default_appearance(Parser& p) {
    static const TextureRef povray_default = std::make_shared<Texture>();
    ObjectAppearance appearance;
    appearance.texture = p.default_texture ? p.default_texture : povray_default;
    return appearance;
}

void parse_default(Parser& p, const Token& directive) {
    const Token open = p.expect_open(directive);
    for (;;) {
        const Token token = p.peek();
        if (token.is(Symbol::rbrace)) break;
        p.next();
        if (token.is(Keyword::texture)) {
            const TextureRef texture = parse_texture(p, token);
            if (texture->kind == Texture::Kind::layered)
                p.fail(token, "the default texture cannot be layered (POV-Ray's rule)");
            if (texture->kind == Texture::Kind::patterned)
                p.fail(token,
                       "the default texture cannot be patterned, tiles or a material_map "
                       "(POV-Ray's rule)");
            p.default_texture = texture;
            continue;
        }
        auto texture = std::make_shared<Texture>(default_texture(p));
        if (token.is(Keyword::pigment))
            texture->pigment = *parse_pigment(p, token);
        else if (token.is(Keyword::normal))
            texture->normal = parse_normal(p, token);
        else if (token.is(Keyword::finish))
            texture->finish = *parse_finish(p, token);
        else
            p.fail_identifier(token, fmt::format("texture, pigment, normal, finish or {}",
                                                 closing_purpose(p, directive, open)));
        p.default_texture = texture;
    }
    p.expect_close(directive, open);
}

}  // namespace rayset::tracer
