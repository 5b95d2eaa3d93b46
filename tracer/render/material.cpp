// POV-Ray texture -> physical material, and the mixed BSDF (see material.h and README.md).
#include "tracer/render/material.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <vector>

#include <fmt/format.h>

#include "core/error.h"
#include "tracer/scene_language/grammar.h"
#include "tracer/scene_language/normal_perturbation.h"

namespace rayset::tracer {

namespace {

Rgb clamp01(Rgb a) {
    auto c = [](double v) { return std::min(1.0, std::max(0.0, v)); };
    return {c(a.red), c(a.green), c(a.blue)};
}

// Keeps every channel of diffuse + glossy + mirror_max + transmission at or below one, so no
// surface reflects more than it receives: the specular lobes keep their weight, the diffuse
// lobe takes what is left (POV-Ray adds them without such a limit).
void conserve_energy(Material& m) {
    auto fix = [](double& d, double& g, double& r, double& t) {
        const double specular = g + r + t;
        if (specular > 1) {
            g /= specular, r /= specular, t /= specular;
            d = 0;
        } else {
            d = std::min(d, 1 - specular);
        }
    };
    const Rgb mirror_before = m.mirror_max;
    fix(m.diffuse.red, m.glossy.red, m.mirror_max.red, m.transmission.red);
    fix(m.diffuse.green, m.glossy.green, m.mirror_max.green, m.transmission.green);
    fix(m.diffuse.blue, m.glossy.blue, m.mirror_max.blue, m.transmission.blue);
    auto lower = [](Rgb a, Rgb b) {
        return Rgb{std::min(a.red, b.red), std::min(a.green, b.green), std::min(a.blue, b.blue)};
    };
    m.mirror_min = lower(m.mirror_min, m.mirror_max);
    // The metallic weights are the plain ones tinted: scaled alike.
    auto ratio = [](double after, double before) { return before > 0 ? after / before : 0.0; };
    m.mirror_max_metal = Rgb{ratio(m.mirror_max.red, mirror_before.red),
                             ratio(m.mirror_max.green, mirror_before.green),
                             ratio(m.mirror_max.blue, mirror_before.blue)} *
                         m.mirror_max_metal;
    m.mirror_min_metal = lower(m.mirror_min_metal, m.mirror_max_metal);
}

// What the renderer does not render of POV-Ray's appearance is refused, never approximated:
// it renders the pigments and normals the scene language evaluates, layered and patterned
// textures of them, the finish keywords of README.md, and an interior's ior (its fade and
// media are interior_media.h's).
class Refusal {
public:
    explicit Refusal(const ObjectInstance& object) : object_(object) {}
    [[noreturn]] void fail(const std::string& feature, const SourceLocation& where) const {
        const SourceLocation& at = where.file.empty() ? object_.location : where;
        throw Error(fmt::format("not supported: {} at {}", feature, at.str()));
    }
    // A plain texture, layers of plain textures, or a texture pattern over textures.
    void check_texture(const Texture& texture) const {
        if (texture.kind == Texture::Kind::layered) {
            for (const TextureRef& layer : texture.layers) check_texture(*layer);
        } else if (texture.kind == Texture::Kind::patterned) {
            check_texture_pattern(texture);
        } else {
            check_plain_texture(texture);
        }
    }
    void check_texture_pattern(const Texture& texture) const {
        const Pattern& pattern = *texture.pattern;
        if (!pattern_is_evaluable(pattern))
            fail(fmt::format("patterned textures ({})", pattern_name(pattern.kind)),
                 pattern.location);
        if (!texture.map || texture.map->entries.empty())
            fail("a texture pattern without textures", texture.location);
        for (const BlendMapEntry& entry : texture.map->entries) {
            if (!entry.texture) fail("a texture pattern without textures", texture.location);
            check_texture(*entry.texture);
        }
    }
    void check_plain_texture(const Texture& texture) const {
        check_pigment(texture.pigment);
        if (texture.normal && !normal_is_evaluable(*texture.normal)) {
            const Pattern& pattern = *texture.normal->pattern;
            const char* detail = pattern.kind == PatternKind::bump_map
                                     ? " other than map_type 0 of colours"
                                 : !texture.normal->map        ? ""
                                 : list_size(pattern.kind) > 0 ? " with a list of normals"
                                                               : " with a normal_map or slope_map";
            fail(fmt::format("normal '{}'{}", pattern_name(pattern.kind), detail),
                 pattern.location);
        }
        check_finish(*texture.finish);
    }
    // A patterned pigment is rendered where its colour is known exactly at every point
    // (evaluate_pigment: no surface coordinates, function images or unevaluated patterns).
    void check_pigment(const Pigment& pigment) const {
        if (pigment.pattern->kind == PatternKind::image_map && pigment.pattern->image)
            check_image_map(*pigment.pattern->image);
        if (pigment.pattern->kind != PatternKind::plain && !pigment_is_evaluable(pigment))
            fail(fmt::format("pigment pattern '{}'", pattern_name(pigment.pattern->kind)),
                 pigment.pattern->location);
    }
    // What image_mapping.h does not lay on space as POV-Ray does.
    void check_image_map(const ImageMap& image) const {
        if (!image.pixels)
            fail(image.file_type == "function"
                     ? std::string("image_map of a function image")
                     : fmt::format("{} images (convert it to PNG, TGA or EXR)", image.file_type),
                 image.location);
        for (const auto* amounts : {&image.filter, &image.transmit})
            for (const ImageMap::PaletteAmount& entry : *amounts)
                if (entry.index >= 0 && image.pixels->indices.empty())
                    fail(
                        "image_map filter or transmit of a palette entry of an image other "
                        "than a PNG palette image",
                        image.location);
        if (image.interpolate == 3) fail("image_map interpolate 3 (bicubic)", image.location);
        if (image.map_type != 0 && image.map_type != 1 && image.map_type != 2 &&
            image.map_type != 5)
            fail(fmt::format("image_map map_type {}", image.map_type), image.location);
    }
    void check_finish(const Finish& f) const {
        struct Unrendered {
            bool present;
            const char* feature;
        };
        const Unrendered unrendered[] = {
            {f.diffuse_albedo || f.specular_albedo || f.phong_albedo, "finish 'albedo'"},
            {f.diffuse_back != 0, "finish diffuse with a back-side amount"},
            {f.reflection_exponent != 1, "reflection 'exponent'"},
            {f.irid_amount != 0, "finish 'irid'"},
            {f.subsurface, "finish 'subsurface'"},
            {f.legacy_ior != 0 || f.legacy_refraction != 0 || f.legacy_caustics != 0,
             "ior, refraction or caustics in a finish (give them in interior { })"},
        };
        for (const Unrendered& item : unrendered)
            if (item.present) fail(item.feature, f.location);
    }
    void check_interior(const Interior& interior) const {
        if (interior.dispersion != 1) fail("interior 'dispersion'", interior.location);
    }

private:
    const ObjectInstance& object_;
};

// The physical material of a pigment colour under a finish (README.md beside this file),
// before conserve_energy (applied once to what the texture's parts make together).
Material material_of(const Colour& c, const Finish& f, double ior, double emission_scale) {
    Material m;
    const Rgb pigment = clamp01(c.rgb());
    const double opacity = std::max(0.0, 1 - c.filter - c.transmit);
    m.diffuse = (opacity * f.diffuse) * pigment;
    m.transmission = clamp01(c.filter * pigment + Rgb{c.transmit, c.transmit, c.transmit});
    m.ior = ior;

    // POV-Ray's `specular` is a Blinn highlight of exponent 1/roughness; a Phong lobe about the
    // mirror direction with a quarter of that exponent has nearly the same width.
    double amount = 0, exponent = 0;
    if (f.specular > 0)
        amount += f.specular, exponent = std::max(exponent, 0.25 / std::max(f.roughness, 1e-6));
    if (f.phong > 0) amount += f.phong, exponent = std::max(exponent, f.phong_size);
    const Rgb white{1, 1, 1};
    m.glossy = amount * ((1 - f.metallic) * white + f.metallic * pigment);
    m.glossy_exponent = std::max(exponent, 1.0);

    m.mirror_min = clamp01(f.reflection_min);
    m.mirror_max = clamp01(f.reflection_max);
    m.mirror_falloff = f.reflection_falloff;
    m.mirror_fresnel = f.reflection_fresnel;
    m.mirror_metallic = std::clamp(f.reflection_metallic, 0.0, 1.0);
    m.mirror_min_metal = m.mirror_min * pigment;
    m.mirror_max_metal = m.mirror_max * pigment;
    m.emission = (emission_scale * opacity) * (f.emission * pigment);  // as POV-Ray weighs it
    return m;
}

void add_spectra(Material& m) {
    m.emission_spectrum = IlluminantSpectrum(m.emission);
    m.spectra = {upsample_reflectance(m.diffuse),
                 upsample_reflectance(m.glossy),
                 upsample_reflectance(m.mirror_min),
                 upsample_reflectance(m.mirror_max),
                 upsample_reflectance(m.transmission),
                 {},
                 {}};
    if (m.mirror_metallic > 0) {
        m.spectra.mirror_min_metal = upsample_reflectance(m.mirror_min_metal);
        m.spectra.mirror_max_metal = upsample_reflectance(m.mirror_max_metal);
    }
}

// Adds `m` weighted per channel to `sum`, lobe by lobe: what layers and texture patterns
// make. The shapes of the lobes (highlight exponent, mirror falloff and Fresnel) come from the
// parts that have them; check_lobe_shapes makes sure those agree.
void add_weighted(Material& sum, const Material& m, Rgb weight) {
    if (!is_black(m.glossy)) sum.glossy_exponent = m.glossy_exponent;
    if (!is_black(m.mirror_max)) {
        sum.mirror_falloff = m.mirror_falloff;
        sum.mirror_fresnel = m.mirror_fresnel;
        sum.mirror_metallic = m.mirror_metallic;
    }
    sum.ior = m.ior;
    sum.diffuse += weight * m.diffuse;
    sum.glossy += weight * m.glossy;
    sum.mirror_min += weight * m.mirror_min;
    sum.mirror_max += weight * m.mirror_max;
    sum.mirror_min_metal += weight * m.mirror_min_metal;
    sum.mirror_max_metal += weight * m.mirror_max_metal;
    sum.transmission += weight * m.transmission;
    sum.emission += weight * m.emission;
}

const Rgb kWhite{1, 1, 1};

// A number in [0, 1) fixed by a point's coordinates and scattered from one point to the next.
double grain(Vec3 p) {
    uint64_t h = 0x9e3779b97f4a7c15u;
    for (const double v : {p.x, p.y, p.z}) {
        uint64_t bits;
        std::memcpy(&bits, &v, sizeof bits);
        h = (h ^ bits) * 0xff51afd7ed558ccdu;
        h ^= h >> 33;
    }
    h *= 0xc4ceb9fe1a85ec53u;
    h ^= h >> 33;
    return double(h >> 11) * 0x1.0p-53;
}

// finish { crand c }: POV-Ray darkens the diffuse light at each point by c u, u uniform in
// [0, 1) and drawn anew at each point; here the diffuse albedo, as a grain fixed to the point.
void darken_by_crand(Material& m, double crand, Vec3 point) {
    const double dark = crand * grain(point);
    m.diffuse = {std::max(0.0, m.diffuse.red - dark), std::max(0.0, m.diffuse.green - dark),
                 std::max(0.0, m.diffuse.blue - dark)};
}

// Every plain texture a texture is made of.
void for_each_plain_texture(const Texture& texture,
                            const std::function<void(const Texture&)>& visit) {
    if (texture.kind == Texture::Kind::layered) {
        for (const TextureRef& layer : texture.layers) for_each_plain_texture(*layer, visit);
    } else if (texture.kind == Texture::Kind::patterned) {
        for (const BlendMapEntry& entry : texture.map->entries)
            for_each_plain_texture(*entry.texture, visit);
    } else {
        visit(texture);
    }
}

bool texture_varies(const Texture& texture) {
    bool varies = texture.kind == Texture::Kind::patterned;
    for_each_plain_texture(texture, [&](const Texture& plain) {
        varies = varies || plain.pigment.pattern->kind != PatternKind::plain ||
                 (plain.normal && plain.normal->pattern->kind != PatternKind::plain) ||
                 plain.finish->crand != 0;
    });
    return varies;
}

}  // namespace

// The material of a texture at a point: a plain texture's pigment colour under its finish,
// tilted by its normal; a layered one's layers from the bottom up, each seen through the
// filter and transmit of the layers above it (POV-Ray's layering); a texture pattern's
// textures blended by its map.
struct ObjectMaterial::Maker {
    double ior, emission_scale;
    const ColourDecoding& decoding;
    Vec3 normal;  // the surface's outward geometric normal at the point

    bool make(const Texture& texture, Vec3 point, Material& out) const {
        if (!combine(texture, point, out)) return false;
        conserve_energy(out);
        return true;
    }

private:
    bool combine(const Texture& texture, Vec3 point, Material& out) const {
        if (texture.kind == Texture::Kind::layered) return layered(texture, point, out);
        if (texture.kind == Texture::Kind::patterned) return patterned(texture, point, out);
        Colour colour = texture.pigment.colour;
        if (texture.pigment.pattern->kind != PatternKind::plain &&
            !evaluate_pigment(texture.pigment, point, colour))
            return false;
        out = material_of(decoding(colour), *texture.finish, ior, emission_scale);
        if (texture.finish->crand > 0) darken_by_crand(out, texture.finish->crand, point);
        return !texture.normal || normal_perturbation(*texture.normal, point, normal, out.bump);
    }
    bool layered(const Texture& texture, Vec3 point, Material& out) const {
        if (!combine(*texture.layers.front(), point, out)) return false;
        for (size_t i = 1; i < texture.layers.size(); ++i) {
            Material layer;
            if (!combine(*texture.layers[i], point, layer)) return false;
            const Rgb through = layer.transmission;
            layer.transmission = {};
            Material sum;
            add_weighted(sum, layer, kWhite);
            add_weighted(sum, out, through);
            const double below = (through.red + through.green + through.blue) / 3;
            sum.bump = (1 - below) * layer.bump + below * out.bump;
            out = sum;
        }
        return true;
    }
    bool patterned(const Texture& texture, Vec3 point, Material& out) const {
        double value = 0;
        MapBlend blend;
        if (!evaluate_pattern(*texture.pattern, point, value) ||
            !look_up_map(*texture.map, value, blend))
            return false;
        const auto& entries = texture.map->entries;
        if (!combine(*entries[blend.low].texture, point, out)) return false;
        if (blend.weight == 0) return true;
        Material high;
        if (!combine(*entries[blend.high].texture, point, high)) return false;
        Material sum;
        add_weighted(sum, out, (1 - blend.weight) * kWhite);
        add_weighted(sum, high, blend.weight * kWhite);
        sum.bump = (1 - blend.weight) * out.bump + blend.weight * high.bump;
        out = sum;
        return true;
    }
};

namespace {

// One material holds one highlight and one mirror lobe: the textures a layered or patterned
// texture combines must agree on their shapes where they have them.
void check_lobe_shapes(const Texture& texture, const Refusal& refusal) {
    const Material* glossy = nullptr;
    const Material* mirror = nullptr;
    std::vector<Material> parts;
    for_each_plain_texture(texture, [&](const Texture& plain) {
        parts.push_back(material_of({1, 1, 1, 0, 0}, *plain.finish, 1, 1));
    });
    for (const Material& part : parts) {
        if (!is_black(part.glossy)) {
            if (glossy && glossy->glossy_exponent != part.glossy_exponent)
                refusal.fail("textures combining highlights of different sizes", texture.location);
            glossy = &part;
        }
        if (!is_black(part.mirror_max)) {
            if (mirror && (mirror->mirror_falloff != part.mirror_falloff ||
                           mirror->mirror_fresnel != part.mirror_fresnel ||
                           mirror->mirror_metallic != part.mirror_metallic))
                refusal.fail(
                    "textures combining reflections of different falloff, fresnel or "
                    "metallic",
                    texture.location);
            mirror = &part;
        }
    }
}

}  // namespace

ObjectMaterial::ObjectMaterial(const ObjectInstance& object, double emission_scale,
                               const ColourDecoding& decoding)
    : emission_scale_(emission_scale), decoding_(decoding) {
    const Refusal refusal(object);
    const ObjectAppearance& appearance = object.appearance;
    if (appearance.texture) refusal.check_texture(*appearance.texture);
    if (appearance.interior_texture)
        refusal.fail("interior_texture", appearance.interior_texture->location);
    if (appearance.interior) refusal.check_interior(*appearance.interior);
    if (!appearance.texture) return;  // POV-Ray renders an untextured object black
    ior_ = appearance.interior ? appearance.interior->ior : 1.0;
    const Texture& texture = *appearance.texture;
    check_lobe_shapes(texture, refusal);
    for_each_plain_texture(texture, [&](const Texture& plain) {
        emits_ = emits_ || !is_black(plain.finish->emission);
    });
    if (texture_varies(texture)) {
        texture_ = appearance.texture;
        return;
    }
    maker({0, 0, 1}).make(texture, {}, uniform_);
    emits_ = !is_black(uniform_.emission);
    add_spectra(uniform_);
}

ObjectMaterial::Maker ObjectMaterial::maker(Vec3 normal) const {
    return {ior_, emission_scale_, decoding_, normal};
}

const Material& ObjectMaterial::at(Vec3 point, Vec3 normal,
                                   std::optional<Material>& scratch) const {
    if (!texture_) return uniform_;
    if (!maker(normal).make(*texture_, point, scratch.emplace()))
        throw Error(
            fmt::format("not supported: the texture at {} (its value at ({}, {}, {}) is "
                        "not known)",
                        texture_->location.str(), point.x, point.y, point.z));
    return *scratch;
}

LobeColours<Rgb> lobe_colours(const Material& m, NoWavelengths) {
    return {m.diffuse,      m.glossy,           m.mirror_min,      m.mirror_max,
            m.transmission, m.mirror_min_metal, m.mirror_max_metal};
}

LobeColours<SampledSpectrum> lobe_colours(const Material& m, const SampledWavelengths& w) {
    auto at = [&](const Rgb& rgb, const ReflectanceSpectrum& spectrum) {
        SampledSpectrum s;
        if (is_black(rgb)) return s;
        for (int i = 0; i < kWavelengths; ++i) s.v[i] = spectrum(w.nm[i]);
        return s;
    };
    return {at(m.diffuse, m.spectra.diffuse),
            at(m.glossy, m.spectra.glossy),
            at(m.mirror_min, m.spectra.mirror_min),
            at(m.mirror_max, m.spectra.mirror_max),
            at(m.transmission, m.spectra.transmission),
            at(m.mirror_min_metal, m.spectra.mirror_min_metal),
            at(m.mirror_max_metal, m.spectra.mirror_max_metal)};
}

double fresnel_dielectric(double cos_i, double eta) {
    const double sin2_t = (1 - cos_i * cos_i) / (eta * eta);
    if (sin2_t >= 1) return 1;  // total internal reflection
    const double cos_t = std::sqrt(1 - sin2_t);
    const double rs = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    const double rp = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    return 0.5 * (rs * rs + rp * rp);
}

namespace {

// A shading normal tilted by a material's bump; a tilt to or past the surface's plane leaves
// the normal as it is (no side of the surface would face it).
Vec3 tilted(Vec3 shading_normal, Vec3 bump) {
    if (is_zero(bump)) return shading_normal;
    const Vec3 n = shading_normal + bump;
    return dot(n, shading_normal) > 0 ? normalized(n) : shading_normal;
}

}  // namespace

template <class Q>
BsdfOf<Q>::BsdfOf(const Material& material, Vec3 normal, Vec3 shading_normal, Vec3 wo,
                  const WavelengthsFor<Q>& wavelengths)
    : m_(material), c_(lobe_colours(material, wavelengths)), wo_(wo) {
    entering_ = dot(wo, normal) >= 0;
    n_ = entering_ ? normal : -normal;
    shading_normal = tilted(shading_normal, material.bump);
    ns_ = dot(shading_normal, n_) >= 0 ? shading_normal : -shading_normal;
    // The part of the diffuse lobe about a tilted shading normal that lies below the surface
    // is lost; the rest, (1 + cos tilt) / 2 of it (a tilted plane's view of a hemisphere), is
    // scaled up to carry the whole albedo.
    diffuse_scale_ = 2 / (1 + dot(ns_, n_));
    cos_o_ = std::max(0.0, dot(wo, ns_));
    odds_ = lobe_odds(wo);
}

template <class Q>
typename BsdfOf<Q>::LobeOdds BsdfOf<Q>::lobe_odds(Vec3 wo) const {
    // Lobes are picked in proportion to their average albedo; the channel sums give the same
    // ratios with one division instead of eight (this runs at every hit).
    auto sum = [](Rgb a) { return a.red + a.green + a.blue; };
    const double d = sum(m_.diffuse), g = sum(m_.glossy),
                 r = is_black(m_.mirror_max) ? 0 : sum(mirror_weight_rgb(wo)),
                 t = sum(m_.transmission);
    const double total = d + g + r + t;
    if (!(total > 0)) return {};
    const double inverse = 1 / total;
    return {d * inverse, g * inverse, r * inverse, t * inverse};
}

template <class Q>
double BsdfOf<Q>::mirror_fraction(Vec3 wo) const {
    const double c = std::max(0.0, dot(wo, n_));
    return m_.mirror_fresnel ? fresnel_dielectric(c, m_.ior > 1 ? m_.ior : 1.5)
                             : std::pow(1 - c, m_.mirror_falloff);
}

// POV-Ray's metallic reflection keeps the pigment's tint by metallic (1 - F), F this curve of
// the angle of incidence (read back from POV-Ray 3.7's renders of a metallic mirror at 30 to 85
// degrees: F = 0.012, 0.026, 0.059, 0.113, 0.261, 0.461, which it gives to three digits).
namespace {
double metallic_grazing(double cos_o) {
    const double x = std::acos(std::clamp(cos_o, 0.0, 1.0)) / (kPi / 2);
    return std::clamp(0.014567225 / ((x - 1.12) * (x - 1.12)) - 0.011612903, 0.0, 1.0);
}
}  // namespace

template <class Q>
template <class Colour>
Colour BsdfOf<Q>::mirror_weight_of(const Colour& min, const Colour& max, const Colour& min_metal,
                                   const Colour& max_metal, Vec3 wo) const {
    const double fraction = mirror_fraction(wo);
    const Colour plain = min + fraction * (max - min);
    if (m_.mirror_metallic == 0) return plain;
    const double metal = m_.mirror_metallic * (1 - metallic_grazing(std::max(0.0, dot(wo, n_))));
    return (1 - metal) * plain + metal * (min_metal + fraction * (max_metal - min_metal));
}

template <class Q>
Rgb BsdfOf<Q>::mirror_weight_rgb(Vec3 wo) const {
    return mirror_weight_of(m_.mirror_min, m_.mirror_max, m_.mirror_min_metal, m_.mirror_max_metal,
                            wo);
}

template <class Q>
Q BsdfOf<Q>::mirror_weight() const {
    return mirror_weight_of(c_.mirror_min, c_.mirror_max, c_.mirror_min_metal, c_.mirror_max_metal,
                            wo_);
}

template <class Q>
void BsdfOf<Q>::smooth_factors(Vec3 wi, double& diffuse_factor, double& glossy_factor) const {
    diffuse_factor = glossy_factor = 0;
    const double cos_i = dot(wi, ns_);
    if (cos_i <= 0 || dot(wi, n_) <= 0) return;
    diffuse_factor = diffuse_scale_ * cos_i / kPi;
    if (odds_.glossy > 0) {
        const double c = dot(wi, reflect(wo_, ns_));
        if (c > 0)
            glossy_factor =
                cos_i * (m_.glossy_exponent + 2) / (2 * kPi) * std::pow(c, m_.glossy_exponent);
    }
}

template <class Q>
Q BsdfOf<Q>::eval(Vec3 wi) const {
    double diffuse_factor, glossy_factor;
    smooth_factors(wi, diffuse_factor, glossy_factor);
    if (!(diffuse_factor > 0)) return {};
    Q f = diffuse_factor * c_.diffuse;
    if (glossy_factor > 0) f += glossy_factor * c_.glossy;
    return f;
}

template <class Q>
double BsdfOf<Q>::pdf(Vec3 wi) const {
    return smooth_pdf(wi, wo_, odds_);
}

template <class Q>
double BsdfOf<Q>::smooth_pdf(Vec3 sampled, Vec3 given, const LobeOdds& odds) const {
    const double cos_i = dot(sampled, ns_);
    if (cos_i <= 0 || dot(sampled, n_) <= 0) return 0;
    double p = odds.diffuse * cos_i / kPi;
    if (odds.glossy > 0) {
        const double c = dot(sampled, reflect(given, ns_));
        if (c > 0)
            p += odds.glossy * (m_.glossy_exponent + 1) / (2 * kPi) *
                 std::pow(c, m_.glossy_exponent);
    }
    return p;
}

template <class Q>
double BsdfOf<Q>::pdf_reversed(Vec3 wi) const {
    // The BSDF made for wi has the same normals when wi is on wo's side (from the other side
    // it reflects nothing toward wo), and the same lobe odds unless a mirror lobe's weight
    // changes with the direction.
    const double side = dot(wi, n_);
    if (side < 0 || (side == 0 && !entering_)) return 0;
    return smooth_pdf(wo_, wi, is_black(m_.mirror_max) ? odds_ : lobe_odds(wi));
}

template <class Q>
bool BsdfOf<Q>::sample(double u_lobe, double u1, double u2, BsdfSampleOf<Q>& out) const {
    if (u_lobe < odds_.diffuse &&
        odds_.glossy == 0) {  // diffuse alone: f cos / pdf is the albedo over p_diffuse
        out.wi = normalized(Frame(ns_).to_world(cosine_hemisphere(u1, u2)));
        const double cos_i = dot(out.wi, ns_);
        out.delta = false;
        out.pdf = odds_.diffuse * cos_i / kPi;
        if (out.pdf <= 0 || dot(out.wi, n_) <= 0) return false;
        out.weight = (diffuse_scale_ / odds_.diffuse) * c_.diffuse;
        return true;
    }
    if (u_lobe < odds_.diffuse + odds_.glossy) {
        const Vec3 local = u_lobe < odds_.diffuse ? cosine_hemisphere(u1, u2)
                                                  : phong_lobe(m_.glossy_exponent, u1, u2);
        out.wi =
            normalized(Frame(u_lobe < odds_.diffuse ? ns_ : reflect(wo_, ns_)).to_world(local));
        out.pdf = pdf(out.wi);
        out.delta = false;
        if (out.pdf <= 0) return false;
        out.weight = (1 / out.pdf) * eval(out.wi);
        return true;
    }
    out.pdf = 0;
    out.delta = true;
    if (u_lobe < odds_.diffuse + odds_.glossy + odds_.mirror) {
        out.wi = reflect(wo_, n_);
        out.weight = (1 / odds_.mirror) * mirror_weight();
        return true;
    }
    if (odds_.dielectric <= 0) return false;
    // Smooth dielectric: reflect with probability F, else refract; radiance is compressed by
    // eta^2 on entering a denser medium (pbrt's non-symmetric BTDF for radiance transport).
    const double eta = entering_ ? m_.ior : 1 / m_.ior;
    const double cos_i = std::max(0.0, dot(wo_, n_));
    const double fresnel = fresnel_dielectric(cos_i, eta);
    const Q weight = (1 / odds_.dielectric) * c_.transmission;
    if (u1 < fresnel) {
        out.wi = reflect(wo_, n_);
        out.weight = weight;
        return true;
    }
    const double sin2_t = (1 - cos_i * cos_i) / (eta * eta);
    const double cos_t = std::sqrt(std::max(0.0, 1 - sin2_t));
    out.wi = normalized((-1 / eta) * wo_ + (cos_i / eta - cos_t) * n_);
    out.weight = (1 / (eta * eta)) * weight;
    return true;
}

template class BsdfOf<Rgb>;
template class BsdfOf<SampledSpectrum>;

const Material& white_lambertian() {
    static const Material white = [] {
        Material m;
        m.diffuse = {1, 1, 1};
        m.spectra.diffuse = ReflectanceSpectrum::constant(1);
        return m;
    }();
    return white;
}

}  // namespace rayset::tracer
