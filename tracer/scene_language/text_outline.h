// The outline of a string in a TrueType font, laid out as POV-Ray's text object lays it out
// (read back from its renders): glyphs in the x-y plane, one em high (font units over units per
// em), the baseline on y = 0, the first glyph's left edge (not its origin) at x = 0, each next
// glyph moved by the advance width, the font's kerning and the text's offset; the solid
// extrudes the outline from z = 0 to the thickness.
//
// Outlines come from FreeType as closed contours of straight and quadratic pieces (TrueType's
// own curves: no tessellation, so the geometry is exact). Filled is what the nonzero winding
// rule fills.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/geometry.h"

namespace rayset::tracer {

struct TextOutline {
    // A quadratic Bezier piece from a through control c to b (a straight piece: c midway).
    struct Piece {
        double ax, ay, cx, cy, bx, by;
        bool filled_left;  // the filled side is left of the direction of travel

        // The point at u in [0, 1] and half its derivative (the tangent's direction).
        double x(double u) const { return ((ax - 2 * cx + bx) * u + 2 * (cx - ax)) * u + ax; }
        double y(double u) const { return ((ay - 2 * cy + by) * u + 2 * (cy - ay)) * u + ay; }
        double dx(double u) const { return (1 - u) * (cx - ax) + u * (bx - cx); }
        double dy(double u) const { return (1 - u) * (cy - ay) + u * (by - cy); }
    };
    std::vector<Piece> pieces;
    double min_x = 0, min_y = 0, max_x = 0, max_y = 0;  // bounds of the pieces

    // Nonzero winding of the outline around (x, y).
    bool inside(double x, double y) const;
};

// The outline of `text` (its bytes taken as Latin-1 code points) in the font at `font_path`,
// advanced by `offset` (x, y) after each character. Throws rayset::Error naming the font when
// FreeType cannot read it or its outlines are cubic (CFF fonts).
std::shared_ptr<const TextOutline> load_text_outline(const std::string& font_path,
                                                     const std::string& text, Vec3 offset);

}  // namespace rayset::tracer
