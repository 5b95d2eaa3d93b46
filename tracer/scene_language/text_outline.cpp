#include "tracer/scene_language/text_outline.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H

#include "core/error.h"
#include "tracer/scene_language/quadratic.h"

namespace rayset::tracer {
namespace {

// The pieces of one glyph, placed at the pen, in ems.
struct GlyphBuilder {
    double scale = 1, pen_x = 0, pen_y = 0;
    double last_x = 0, last_y = 0;
    bool cubic = false;
    std::vector<TextOutline::Piece> pieces;

    double x(const FT_Vector* v) const { return pen_x + scale * double(v->x); }
    double y(const FT_Vector* v) const { return pen_y + scale * double(v->y); }
    void add(double cx, double cy, double bx, double by) {
        pieces.push_back({last_x, last_y, cx, cy, bx, by, false});
        last_x = bx, last_y = by;
    }
};

int move_to(const FT_Vector* to, void* user) {
    auto* g = static_cast<GlyphBuilder*>(user);
    g->last_x = g->x(to), g->last_y = g->y(to);
    return 0;
}
int line_to(const FT_Vector* to, void* user) {
    auto* g = static_cast<GlyphBuilder*>(user);
    const double bx = g->x(to), by = g->y(to);
    g->add(0.5 * (g->last_x + bx), 0.5 * (g->last_y + by), bx, by);
    return 0;
}
int conic_to(const FT_Vector* control, const FT_Vector* to, void* user) {
    auto* g = static_cast<GlyphBuilder*>(user);
    g->add(g->x(control), g->y(control), g->x(to), g->y(to));
    return 0;
}
int cubic_to(const FT_Vector*, const FT_Vector*, const FT_Vector*, void* user) {
    static_cast<GlyphBuilder*>(user)->cubic = true;
    return 1;
}

// Twice the signed area the pieces enclose (positive: counter-clockwise), their curves' areas
// included (a quadratic's bulge is 2/3 of its control triangle).
double signed_area(const std::vector<TextOutline::Piece>& pieces) {
    double sum = 0;
    for (const TextOutline::Piece& p : pieces) {
        sum += p.ax * p.by - p.bx * p.ay;
        sum += 2.0 / 3.0 * ((p.cx - p.ax) * (p.by - p.ay) - (p.cy - p.ay) * (p.bx - p.ax));
    }
    return sum;
}

struct Library {
    FT_Library library = nullptr;
    FT_Face face = nullptr;
    ~Library() {
        if (face) FT_Done_Face(face);
        if (library) FT_Done_FreeType(library);
    }
};

}  // namespace

bool TextOutline::inside(double x, double y) const {
    if (x < min_x || x > max_x || y < min_y || y > max_y) return false;
    int winding = 0;
    for (const Piece& p : pieces) {
        if ((p.ay > y && p.cy > y && p.by > y) || (p.ay < y && p.cy < y && p.by < y)) continue;
        // Where the piece crosses the level y on [0, 1), to the right of x, and which way.
        double roots[2];
        const int n = solve_quadratic(p.ay - 2 * p.cy + p.by, 2 * (p.cy - p.ay), p.ay - y, roots);
        for (int i = 0; i < n; ++i) {
            const double u = roots[i];
            if (!(u >= 0 && u < 1) || p.x(u) <= x) continue;
            const double rising = p.dy(u);
            winding += rising > 0 ? 1 : rising < 0 ? -1 : 0;
        }
    }
    return winding != 0;
}

std::shared_ptr<const TextOutline> load_text_outline(const std::string& font_path,
                                                     const std::string& text, Vec3 offset) {
    Library ft;
    if (FT_Init_FreeType(&ft.library) != 0) throw Error("cannot start FreeType");
    if (FT_New_Face(ft.library, font_path.c_str(), 0, &ft.face) != 0)
        throw Error(fmt::format("cannot read the font {} (FreeType reads TrueType and OpenType)",
                                font_path));
    if (!FT_IS_SCALABLE(ft.face) || ft.face->units_per_EM == 0)
        throw Error(fmt::format("the font {} has no outlines", font_path));
    auto outline = std::make_shared<TextOutline>();
    const double scale = 1.0 / ft.face->units_per_EM;
    const FT_Outline_Funcs funcs = {move_to, line_to, conic_to, cubic_to, 0, 0};
    double pen_x = 0, pen_y = 0;
    FT_UInt previous = 0;
    for (size_t i = 0; i < text.size(); ++i) {
        const auto ch = static_cast<unsigned char>(text[i]);
        const FT_UInt index = FT_Get_Char_Index(ft.face, ch);
        FT_Vector kerning{0, 0};
        if (i > 0 && FT_HAS_KERNING(ft.face) &&
            FT_Get_Kerning(ft.face, previous, index, FT_KERNING_UNSCALED, &kerning) == 0)
            pen_x += scale * double(kerning.x);
        previous = index;
        if (FT_Load_Glyph(ft.face, index, FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING) != 0 ||
            ft.face->glyph->format != FT_GLYPH_FORMAT_OUTLINE)
            throw Error(
                fmt::format("cannot read the outline of '{}' in the font {}", char(ch), font_path));
        GlyphBuilder glyph;
        // POV-Ray starts the text at its first glyph's left edge: that side bearing is dropped.
        if (i == 0) pen_x = -scale * double(ft.face->glyph->metrics.horiBearingX);
        glyph.scale = scale, glyph.pen_x = pen_x, glyph.pen_y = pen_y;
        FT_Outline_Decompose(&ft.face->glyph->outline, &funcs, &glyph);
        if (glyph.cubic)
            throw Error(
                fmt::format("not supported: text in the font {} (cubic outlines)", font_path));
        const bool filled_left = signed_area(glyph.pieces) > 0;
        for (TextOutline::Piece& piece : glyph.pieces) {
            piece.filled_left = filled_left;
            outline->pieces.push_back(piece);
        }
        pen_x += scale * double(ft.face->glyph->advance.x) + offset.x;
        pen_y += offset.y;
    }
    bool first = true;
    for (const TextOutline::Piece& p : outline->pieces)
        for (auto [x, y] : {std::pair{p.ax, p.ay}, std::pair{p.cx, p.cy}, std::pair{p.bx, p.by}}) {
            if (first) outline->min_x = outline->max_x = x, outline->min_y = outline->max_y = y;
            first = false;
            outline->min_x = std::min(outline->min_x, x),
            outline->max_x = std::max(outline->max_x, x);
            outline->min_y = std::min(outline->min_y, y),
            outline->max_y = std::max(outline->max_y, y);
        }
    return outline;
}

}  // namespace rayset::tracer
