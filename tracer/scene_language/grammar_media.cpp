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
        p.fail(at, fmt::format("the scattering type must be 1 to 5, found {}", media.scattering_type));
    p.accept_comma();
    media.scattering = parse_rgb(p);
    for (;;) {
        if (p.peek_is(Symbol::rbrace)) break;
        const Token item = p.next();
        if (item.is(Keyword::eccentricity)) media.eccentricity = p.parse_float("after 'eccentricity'");
        else if (item.is(Keyword::extinction)) media.extinction = p.parse_float("after 'extinction'");
        else p.fail_identifier(item, fmt::format("eccentricity, extinction or {}", closing_purpose(p, keyword, open)));
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
            p.fail(at, fmt::format("the maximum number of media samples ({}) is below the minimum ({})",
                                   media.samples_max, media.samples_min));
    }
}

// One media item other than transforms; false when the next token is none.
bool parse_media_item(Parser& p, Media& media) {
    const Token token = p.peek();
    auto after = [&] { return fmt::format("after '{}'", p.word(token)); };
    switch (token.kind == TokenKind::word && is_keyword(token.name) ? static_cast<Keyword>(token.name) : Keyword::size_) {
        case Keyword::method: {
            p.next();
            const Token at = p.peek();
            media.method = p.parse_int(after(), 1);
            if (media.method > 3) p.fail(at, fmt::format("the media method must be 1, 2 or 3, found {}", media.method));
            break;
        }
        case Keyword::intervals: p.next(), media.intervals = p.parse_int(after(), 1); break;
        case Keyword::samples: p.next(), parse_samples(p, media); break;
        case Keyword::confidence: p.next(), media.confidence = p.parse_float(after()); break;
        case Keyword::variance: p.next(), media.variance = p.parse_float(after()); break;
        case Keyword::ratio: p.next(), media.ratio = p.parse_float(after()); break;
        case Keyword::jitter: p.next(), media.jitter = p.parse_float(after()); break;
        case Keyword::aa_level: p.next(), media.aa_level = p.parse_int(after(), 1); break;
        case Keyword::aa_threshold: p.next(), media.aa_threshold = p.parse_float(after()); break;
        case Keyword::absorption: p.next(), media.absorption = parse_rgb(p); break;
        case Keyword::emission: p.next(), media.emission = parse_rgb(p); break;
        case Keyword::scattering: p.next(), parse_scattering(p, media, token); break;
        case Keyword::density: p.next(), media.densities.push_back(parse_density(p, token)); break;
        default: return false;
    }
    return true;
}

}  // namespace

MediaRef parse_media(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    auto media = std::make_shared<Media>();
    MediaRef declared;
    if (take_declared(p, declared)) *media = *declared;
    media->location = p.location_of(keyword);
    for (;;) {
        if (p.peek_is(Symbol::rbrace)) break;
        Matrix4 transform;
        if (p.parse_transform_item(transform)) {
            // Only the densities written so far move (reference 3.4.8).
            transform_media(*media, transform);
        } else if (!parse_media_item(p, *media)) {
            p.fail_identifier(p.peek(), fmt::format("a media keyword or {}", closing_purpose(p, keyword, open)));
        }
    }
    p.expect_close(keyword, open);
    return media;
}

// The items of an interior body after its identifier, into `interior`.
void parse_interior_items(Parser& p, Interior& interior, const Token& keyword, const Token& open) {
    for (;;) {
        const Token token = p.peek();
        if (token.is(Symbol::rbrace)) break;
        auto after = [&] { return fmt::format("after '{}'", p.word(token)); };
        p.next();
        if (token.is(Keyword::ior)) {
            const Token at = p.peek();
            interior.ior = p.parse_float(after());
            if (!(interior.ior > 0)) p.fail(at, "ior must be positive");
        } else if (token.is(Keyword::caustics)) {
            interior.caustics = p.parse_float(after());
        } else if (token.is(Keyword::dispersion)) {
            interior.dispersion = p.parse_float(after());
        } else if (token.is(Keyword::dispersion_samples)) {
            interior.dispersion_samples = p.parse_int(after(), 2);
        } else if (token.is(Keyword::fade_distance)) {
            interior.fade_distance = p.parse_float(after());
        } else if (token.is(Keyword::fade_power)) {
            interior.fade_power = p.parse_float(after());
        } else if (token.is(Keyword::fade_color) || token.is(Keyword::fade_colour)) {
            interior.fade_colour = parse_rgb(p);
        } else if (token.is(Keyword::media)) {
            interior.media.push_back(parse_media(p, token));
        } else {
            p.fail_identifier(token, fmt::format("ior, caustics, dispersion, dispersion_samples, fade_distance, "
                                                 "fade_power, fade_color, media or {}",
                                                 closing_purpose(p, keyword, open)));
        }
    }
}

}  // namespace rayset::tracer
