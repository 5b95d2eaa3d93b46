// height_field: the crossings of a line with its triangles and its inside (shape_geometry.h).
//
// The line is clipped to the field's box and walked cell by cell across the x-z grid (each cell
// crossed once, in order), the two triangles of each cell intersected exactly. As POV-Ray's
// trace shows: crossings below water_level are not the field's; smooth normals are interpolated
// across a triangle from normals at its corners; the inside is the part below the surface over
// the unit square.
#include <algorithm>
#include <cmath>

#include "tracer/scene_language/shape_geometry.h"

namespace rayset::tracer {
namespace {

struct Cell {
    int column, row;
};

// The corners of cell (i, j) as points, and its two triangles' corners by index:
// 0 = (i, j), 1 = (i + 1, j), 2 = (i, j + 1), 3 = (i + 1, j + 1).
struct CellCorners {
    Vec3 p[4];
    int column, row;
};

CellCorners corners(const HeightGrid& grid, Cell cell) {
    const double dx = 1.0 / (grid.columns - 1), dz = 1.0 / (grid.rows - 1);
    CellCorners c;
    c.column = cell.column, c.row = cell.row;
    for (int k = 0; k < 4; ++k) {
        const int i = cell.column + (k & 1), j = cell.row + (k >> 1);
        c.p[k] = {i * dx, grid.at(i, j), j * dz};
    }
    return c;
}

constexpr int kTriangles[2][3] = {{0, 1, 2}, {1, 3, 2}};

// The normal at grid point (i, j) from the slopes to its neighbours (one-sided at the edges).
Vec3 grid_normal(const HeightGrid& grid, int i, int j) {
    const int i0 = std::max(0, i - 1), i1 = std::min(grid.columns - 1, i + 1);
    const int j0 = std::max(0, j - 1), j1 = std::min(grid.rows - 1, j + 1);
    const double dx = double(i1 - i0) / (grid.columns - 1), dz = double(j1 - j0) / (grid.rows - 1);
    return normalized(
        Vec3{-(grid.at(i1, j) - grid.at(i0, j)) / dx, 1, -(grid.at(i, j1) - grid.at(i, j0)) / dz});
}

// Möller-Trumbore in double precision; the normal faces up (+y), the field's outside.
void cell_hits(const HeightFieldShape& field, const CellCorners& c, Vec3 o, Vec3 d,
               std::vector<ShapeHit>& hits) {
    for (const auto& tri : kTriangles) {
        const Vec3 a = c.p[tri[0]], b = c.p[tri[1]], e = c.p[tri[2]];
        double t, beta, gamma;
        if (!triangle_crossing(a, b, e, o, d, t, beta, gamma)) continue;
        if (o.y + t * d.y < field.water_level) continue;
        Vec3 normal = cross(e - a, b - a);
        if (normal.y < 0) normal = -normal;
        if (field.smooth) {
            auto at = [&](int k) {
                return grid_normal(*field.grid, c.column + (k & 1), c.row + (k >> 1));
            };
            normal = (1 - beta - gamma) * at(tri[0]) + beta * at(tri[1]) + gamma * at(tri[2]);
        }
        hits.push_back({t, normal});
    }
}

// The height of the surface over (x, z) in the unit square.
double surface_height(const HeightGrid& grid, double x, double z) {
    const double gx = x * (grid.columns - 1), gz = z * (grid.rows - 1);
    const int i = std::min(grid.columns - 2, int(std::floor(gx)));
    const int j = std::min(grid.rows - 2, int(std::floor(gz)));
    const double fx = gx - i, fz = gz - j;
    const double h00 = grid.at(i, j), h10 = grid.at(i + 1, j), h01 = grid.at(i, j + 1),
                 h11 = grid.at(i + 1, j + 1);
    // The diagonal from (i, j + 1) to (i + 1, j) splits the cell.
    if (fx + fz <= 1) return h00 + fx * (h10 - h00) + fz * (h01 - h00);
    return h11 + (1 - fx) * (h01 - h11) + (1 - fz) * (h10 - h11);
}

}  // namespace

void height_field_range(const HeightGrid& grid, double& lowest, double& highest) {
    const auto [low, high] = std::minmax_element(grid.heights.begin(), grid.heights.end());
    lowest = *low, highest = *high;
}

void height_field_hits(const HeightFieldShape& field, Vec3 o, Vec3 d, std::vector<ShapeHit>& out) {
    std::vector<ShapeHit> hits;
    const HeightGrid& grid = *field.grid;
    double lowest = 0, highest = 0;
    height_field_range(grid, lowest, highest);
    // The line's stretch inside the field's box.
    double t0 = -1e300, t1 = 1e300;
    const double lo[3] = {0, lowest, 0}, hi[3] = {1, highest, 1};
    const double origin[3] = {o.x, o.y, o.z}, direction[3] = {d.x, d.y, d.z};
    for (int axis = 0; axis < 3; ++axis) {
        if (direction[axis] == 0) {
            if (origin[axis] < lo[axis] || origin[axis] > hi[axis]) return;
            continue;
        }
        double a = (lo[axis] - origin[axis]) / direction[axis];
        double b = (hi[axis] - origin[axis]) / direction[axis];
        if (a > b) std::swap(a, b);
        t0 = std::max(t0, a), t1 = std::min(t1, b);
    }
    if (t0 > t1) return;
    // Walk the cells the line's x-z shadow crosses from t0 to t1.
    const int columns = grid.columns - 1, rows = grid.rows - 1;
    const Vec3 start = o + t0 * d;
    Cell cell{std::clamp(int(std::floor(start.x * columns)), 0, columns - 1),
              std::clamp(int(std::floor(start.z * rows)), 0, rows - 1)};
    const int step_x = d.x > 0 ? 1 : -1, step_z = d.z > 0 ? 1 : -1;
    auto next_t = [&](double position, double direction_component, int index, int step, int count) {
        if (direction_component == 0) return 1e300;
        const double edge = double(step > 0 ? index + 1 : index) / count;
        return (edge - position) / direction_component;
    };
    for (;;) {
        cell_hits(field, corners(grid, cell), o, d, hits);
        const double tx = next_t(o.x, d.x, cell.column, step_x, columns);
        const double tz = next_t(o.z, d.z, cell.row, step_z, rows);
        if (std::min(tx, tz) > t1) break;
        if (tx < tz)
            cell.column += step_x;
        else
            cell.row += step_z;
        if (cell.column < 0 || cell.column >= columns || cell.row < 0 || cell.row >= rows) break;
    }
    // A line through a shared edge meets both triangles there: one crossing.
    std::sort(hits.begin(), hits.end(),
              [](const ShapeHit& a, const ShapeHit& b) { return a.t < b.t; });
    hits.erase(std::unique(hits.begin(), hits.end(),
                           [](const ShapeHit& a, const ShapeHit& b) {
                               return std::abs(a.t - b.t) <= 1e-12 * (1 + std::abs(a.t));
                           }),
               hits.end());
    out.insert(out.end(), hits.begin(), hits.end());
}

bool height_field_inside(const HeightFieldShape& field, Vec3 p) {
    if (p.x < 0 || p.x > 1 || p.z < 0 || p.z > 1) return false;
    return p.y < surface_height(*field.grid, p.x, p.z);
}

}  // namespace rayset::tracer
