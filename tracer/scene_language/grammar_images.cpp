// Bitmaps used as patterns (reference 3.4.7.6, 3.4.7.7, 3.4.6.2.3, 3.4.6.5.3, 3.4.7.4.2):
// image_map, bump_map, material_map and image_pattern, their file or function image and the
// bitmap modifiers.
#include <fmt/format.h>

#include "core/error.h"
#include "tracer/scene_language/appearance_grammar.h"
#include "tracer/scene_language/parser.h"

namespace rayset::tracer {
namespace {

// POV-Ray's bitmap types.
bool bitmap_type(Parser& p, const Token& token, std::string& type) {
    static constexpr Keyword kTypes[] = {Keyword::gif,  Keyword::iff, Keyword::jpeg, Keyword::pgm,
                                         Keyword::png,  Keyword::ppm, Keyword::sys,  Keyword::tga,
                                         Keyword::tiff, Keyword::exr, Keyword::hdr,  Keyword::bmp};
    for (Keyword keyword : kTypes)
        if (token.is(keyword)) {
            type = p.word(token);
            return true;
        }
    return false;
}

void parse_image_source(Parser& p, ImageMap& image, const Token& keyword) {
    const Token token = p.peek();
    if (token.is(Keyword::function)) {
        p.next();
        image.file_type = "function";
        image.function_width = p.parse_int("as the function image's width", 1);
        p.accept_comma();
        image.function_height = p.parse_int("as the function image's height", 1);
        image.function = p.parse_function(token);
        return;
    }
    if (bitmap_type(p, token, image.file_type)) p.next();
    const Token name_token = p.peek();
    if (!p.starts_string(name_token))
        p.fail_identifier(
            name_token, fmt::format("a file name after the bitmap type in '{}'", p.word(keyword)));
    const std::string name = p.parse_string();
    image.path = resolve_image_file(p, name, name_token, image.file_type, "image file");
    image.pixels = read_scene_image(p, image.path, image.file_type, name_token);
    // gamma and premultiplied belong right after the file name.
    for (;;) {
        if (p.accept(Keyword::gamma)) {
            image.gamma_given = true;
            if (p.accept(Keyword::srgb))
                image.gamma_srgb = true;
            else
                image.gamma = p.parse_float("after 'gamma'");
        } else if (p.accept(Keyword::premultiplied)) {
            image.premultiplied_given = true;
            image.premultiplied = p.parse_optional_bool();
        } else {
            return;
        }
    }
}

// filter / transmit: `PALETTE_INDEX, AMOUNT` or `all AMOUNT`.
ImageMap::PaletteAmount parse_palette_amount(Parser& p, const Token& keyword) {
    ImageMap::PaletteAmount entry;
    if (!p.accept(Keyword::all)) {
        entry.index =
            p.parse_int(fmt::format("as the palette index after '{}'", p.word(keyword)), 0);
        p.accept_comma();
    }
    entry.amount = p.parse_float(fmt::format("as the amount after '{}'", p.word(keyword)));
    return entry;
}

// A bitmap modifier; false when the next token is none.
bool parse_bitmap_modifier(Parser& p, ImageMap& image, const Token& keyword) {
    static const std::vector<KeywordField<ImageMap>> fields = {
        whole_field(Keyword::map_type, &ImageMap::map_type, 0),
        flag_field(Keyword::once, &ImageMap::once),
        whole_field(Keyword::interpolate, &ImageMap::interpolate, 0),
        flag_field(Keyword::use_index, &ImageMap::use_index),
    };
    if (parse_keyword_field(p, image, fields)) return true;
    const Token token = p.peek();
    const bool image_map = keyword.is(Keyword::image_map);
    if (image_map && p.accept(Keyword::filter)) {
        image.filter.push_back(parse_palette_amount(p, token));
    } else if (image_map && p.accept(Keyword::transmit)) {
        image.transmit.push_back(parse_palette_amount(p, token));
    } else if (keyword.is(Keyword::image_pattern) && p.accept(Keyword::use_alpha)) {
        image.use_alpha = true;
    } else if (p.accept(Keyword::use_color) || p.accept(Keyword::use_colour)) {
        image.use_index = false;
    } else {
        return false;
    }
    return true;
}

// ImageMap::colours: what each pixel shows.
std::shared_ptr<const std::vector<Colour>> image_colours(const ImageMap& image,
                                                         const GlobalSettings& global) {
    const ImagePixels& pixels = *image.pixels;
    ImageGamma gamma = pixels.gamma;
    if (image.gamma_given)
        gamma = image.gamma_srgb ? ImageGamma{ImageGamma::Kind::srgb, 1}
                                 : ImageGamma{ImageGamma::Kind::power, image.gamma};
    // The scene's colour numbers encode light with its assumed_gamma.
    const ImageGamma scene{
        global.assumed_gamma_srgb ? ImageGamma::Kind::srgb : ImageGamma::Kind::power,
        global.assumed_gamma};
    double filter_all = 0, transmit_all = 0;
    for (const ImageMap::PaletteAmount& entry : image.filter)
        if (entry.index < 0) filter_all = entry.amount;
    for (const ImageMap::PaletteAmount& entry : image.transmit)
        if (entry.index < 0) transmit_all = entry.amount;
    auto colours = std::make_shared<std::vector<Colour>>();
    colours->reserve(size_t(pixels.width) * size_t(pixels.height));
    for (int row = 0; row < pixels.height; ++row)
        for (int column = 0; column < pixels.width; ++column) {
            const float* v = pixels.pixel(column, row);
            Colour c;
            c.red = scene.encode(gamma.decode(v[0]));
            c.green = scene.encode(gamma.decode(v[1]));
            c.blue = scene.encode(gamma.decode(v[2]));
            c.filter = filter_all;
            c.transmit = pixels.has_alpha ? 1 - v[3] : transmit_all;
            if (!pixels.indices.empty()) {
                const int index =
                    pixels.indices[size_t(row) * size_t(pixels.width) + size_t(column)];
                for (const ImageMap::PaletteAmount& entry : image.filter)
                    if (entry.index == index) c.filter = entry.amount;
                for (const ImageMap::PaletteAmount& entry : image.transmit)
                    if (entry.index == index) c.transmit = entry.amount;
            }
            colours->push_back(c);
        }
    return colours;
}

}  // namespace

std::shared_ptr<const ImagePixels> read_scene_image(Parser& p, const std::string& path,
                                                    const std::string& type, const Token& at) {
    if (!image_type_is_read(type)) return nullptr;  // the renderer refuses it, naming the type
    try {
        return read_image_file(path, type);
    } catch (const Error& e) {
        p.fail(at, e.what());
    }
}

std::string resolve_image_file(Parser& p, const std::string& name, const Token& at,
                               const std::string& type, const std::string& what) {
    // POV-Ray also tries the name with its type's extension.
    if (type == "jpeg") return p.resolve_file(name, at, what, {".jpg", ".jpeg"});
    if (type == "tiff") return p.resolve_file(name, at, what, {".tif", ".tiff"});
    if (type.empty() || type == "sys" || type == "function") return p.resolve_file(name, at, what);
    const std::string extension = "." + type;
    return p.resolve_file(name, at, what, {extension.c_str()});
}

std::shared_ptr<const ImageMap> parse_image(Parser& p, const Token& keyword,
                                            const std::function<bool()>& on_item) {
    const Token open = p.expect_open(keyword);
    auto image = std::make_shared<ImageMap>();
    image->location = p.location_of(keyword);
    bool have_source = false;
    for (;;) {
        const Token token = p.peek();
        if (token.is(Symbol::rbrace)) break;
        std::string type;
        if (!have_source && (bitmap_type(p, token, type) || token.is(Keyword::function) ||
                             p.starts_string(token))) {
            parse_image_source(p, *image, keyword);
            have_source = true;
        } else if (!parse_bitmap_modifier(p, *image, keyword) && !(on_item && on_item())) {
            p.fail_identifier(
                token, fmt::format("{} or {}",
                                   have_source ? "a bitmap modifier" : "a bitmap type and file",
                                   closing_purpose(p, keyword, open)));
        }
    }
    if (!have_source)
        p.fail_expected(fmt::format("a bitmap type and file name in '{}'", p.word(keyword)),
                        p.peek());
    p.expect_close(keyword, open);
    if (image->pixels) image->colours = image_colours(*image, p.scene().global);
    return image;
}

}  // namespace rayset::tracer
