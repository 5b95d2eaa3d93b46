// interior { ... } and media { ... } (reference 3.4.8): refraction, dispersion, attenuation,
// caustics, and participating media with their sampling, scattering and densities.
#include <fmt/format.h>

#include "tracer/scene_language/appearance_grammar.h"

namespace rayset::tracer {
namespace {

Rgb parse_rgb(Parser& p) { return p.parse_colour().rgb(); }

// scattering { TYPE, COLOUR [eccentricity E] [extinction E] }
void parse_scattering(Parser& p, Media& media, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    const Token at = p.peek();
    media.scattering_type = p.parse_int("as the scattering type", 1);
    if (media.scattering_type > 5)
        p.fail(at,
               fmt::format("the scattering type must be 1 to 5, found {}", media.scattering_type));
    p.accept_comma();
    media.scattering = parse_rgb(p);
    for (;;) {
        if (p.peek_is(Symbol::rbrace)) break;
        const Token item = p.next();
        if (item.is(Keyword::eccentricity))
            media.eccentricity = p.parse_float("after 'eccentricity'");
        else if (item.is(Keyword::extinction))
            media.extinction = p.parse_float("after 'extinction'");
        else
            p.fail_identifier(item, fmt::format("eccentricity, extinction or {}",
                                                closing_purpose(p, keyword, open)));
    }
    p.expect_close(keyword, open);
}

// samples MIN [, MAX]: MAX defaults to MIN.
void parse_samples(Parser& p, Media& media) {
    media.samples_min = p.parse_int("as the minimum number of media samples", 1);
    media.samples_max = media.samples_min;
    if (p.accept(Symbol::comma)) {
        const Token at = p.peek();
        media.samples_max = p.parse_int("as the maximum number of media samples", 1);
        if (media.samples_max < media.samples_min)
            p.fail(at,
                   fmt::format("the maximum number of media samples ({}) is below the minimum ({})",
                               media.samples_max, media.samples_min));
    }
}

const std::vector<KeywordField<Media>>& media_fields() {
    static const std::vector<KeywordField<Media>> fields = {
        whole_field(Keyword::intervals, &Media::intervals, 1),
        whole_field(Keyword::aa_level, &Media::aa_level, 1),
        number_field(Keyword::confidence, &Media::confidence),
        number_field(Keyword::variance, &Media::variance),
        number_field(Keyword::ratio, &Media::ratio),
        number_field(Keyword::jitter, &Media::jitter),
        number_field(Keyword::aa_threshold, &Media::aa_threshold),
        colour_field(Keyword::absorption, &Media::absorption),
        colour_field(Keyword::emission, &Media::emission),
    };
    return fields;
}

// One media item other than transforms; false when the next token is none.
bool parse_media_item(Parser& p, Media& media) {
    if (parse_keyword_field(p, media, media_fields())) return true;
    const Token token = p.peek();
    if (p.accept(Keyword::method)) {
        const Token at = p.peek();
        media.method = p.parse_int("after 'method'", 1);
        if (media.method > 3)
            p.fail(at, fmt::format("the media method must be 1, 2 or 3, found {}", media.method));
    } else if (p.accept(Keyword::samples)) {
        parse_samples(p, media);
    } else if (p.accept(Keyword::scattering)) {
        parse_scattering(p, media, token);
    } else if (p.accept(Keyword::density)) {
        media.densities.push_back(parse_density(p, token));
    } else {
        return false;
    }
    return true;
}

}  // namespace

MediaRef parse_media(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    auto media = std::make_shared<Media>();
    MediaRef declared;
    if (p.take_declared(declared)) *media = *declared;
    media->location = p.location_of(keyword);
    for (;;) {
        if (p.peek_is(Symbol::rbrace)) break;
        Matrix4 transform;
        if (p.parse_transform_item(transform)) {
            // Only the densities written so far move (reference 3.4.8).
            transform_media(*media, transform);
        } else if (!parse_media_item(p, *media)) {
            p.fail_identifier(
                p.peek(), fmt::format("a media keyword or {}", closing_purpose(p, keyword, open)));
        }
    }
    p.expect_close(keyword, open);
    return media;
}

namespace {

const std::vector<KeywordField<Interior>>& interior_fields() {
    static const std::vector<KeywordField<Interior>> fields = {
        number_field(Keyword::caustics, &Interior::caustics),
        number_field(Keyword::dispersion, &Interior::dispersion),
        whole_field(Keyword::dispersion_samples, &Interior::dispersion_samples, 2),
        number_field(Keyword::fade_distance, &Interior::fade_distance),
        number_field(Keyword::fade_power, &Interior::fade_power),
        colour_field(Keyword::fade_color, &Interior::fade_colour),
        colour_field(Keyword::fade_colour, &Interior::fade_colour),
    };
    return fields;
}

}  // namespace

// The items of an interior body after its identifier, into `interior`.
void parse_interior_items(Parser& p, Interior& interior, const Token& keyword, const Token& open) {
    for (;;) {
        const Token token = p.peek();
        if (token.is(Symbol::rbrace)) break;
        if (parse_keyword_field(p, interior, interior_fields())) continue;
        if (p.accept(Keyword::ior)) {
            const Token at = p.peek();
            interior.ior = p.parse_float("after 'ior'");
            if (!(interior.ior > 0)) p.fail(at, "ior must be positive");
        } else if (p.accept(Keyword::media)) {
            interior.media.push_back(parse_media(p, token));
        } else {
            p.fail_identifier(token,
                              fmt::format("ior, caustics, dispersion, dispersion_samples, "
                                          "fade_distance, fade_power, fade_color, media or {}",
                                          closing_purpose(p, keyword, open)));
        }
    }
}

}  // namespace rayset::tracer
