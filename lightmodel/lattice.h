// The frame every lattice of a model shares: cubic cells over the bounding box of the ray
// origins. A lattice of resolution N has N cells along the box's longest axis and as many cells
// of the same size as the other axes need (at least one), so the density (128), flux (32) and
// intensity (5) lattices nest and a cell is a cube whatever the box's shape. Lengths in mm.
#pragma once

#include "converters/analytic/analytic_geometry.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace rayset::lightmodel {

struct Box {
    Vec3 lower{1e300, 1e300, 1e300}, upper{-1e300, -1e300, -1e300};
    void extend(Vec3 p) {
        lower = {std::min(lower.x, p.x), std::min(lower.y, p.y), std::min(lower.z, p.z)};
        upper = {std::max(upper.x, p.x), std::max(upper.y, p.y), std::max(upper.z, p.z)};
    }
    bool empty() const { return lower.x > upper.x; }
    bool contains(Vec3 p) const {
        return p.x >= lower.x && p.x <= upper.x && p.y >= lower.y && p.y <= upper.y &&
               p.z >= lower.z && p.z <= upper.z;
    }
    Vec3 extent() const { return upper - lower; }
    double longest() const {
        const Vec3 e = extent();
        return std::max({e.x, e.y, e.z});
    }
};

using Coord = std::array<int32_t, 3>;

class LatticeFrame {
public:
    LatticeFrame() = default;
    // `bounds` is the origins' box; a degenerate box (a flat or point source) still gets one
    // layer of cells, centred on it, and a point source a box of kMinimumExtent.
    // OpenVDB refuses transforms whose determinant (cell size cubed) is below 1e-15.
    static constexpr double kMinimumExtent = 1e-2;  // mm
    LatticeFrame(const Box& bounds, int resolution) : resolution_(resolution) {
        const double longest = std::max(bounds.longest(), kMinimumExtent);
        cell_ = longest / resolution;
        const Vec3 e = bounds.extent();
        const double ext[3] = {e.x, e.y, e.z};
        const double lo[3] = {bounds.lower.x, bounds.lower.y, bounds.lower.z};
        double origin[3];
        for (int a = 0; a < 3; ++a) {
            // The longest axis gets exactly `resolution` cells; the others as many as cover them,
            // centred on the box, so a flat source sits in the middle of its one layer.
            dims_[a] = std::max(1, int(std::ceil(ext[a] / cell_ * (1 - 1e-9))));
            origin[a] = lo[a] + 0.5 * (ext[a] - dims_[a] * cell_);
        }
        origin_ = {origin[0], origin[1], origin[2]};
    }

    // A frame as stored: the inverse of resolution(), origin(), cell_size(), dims().
    static LatticeFrame from_parts(int resolution, Vec3 origin, double cell,
                                   std::array<int32_t, 3> dims) {
        LatticeFrame f;
        f.resolution_ = resolution;
        f.origin_ = origin;
        f.cell_ = cell;
        f.dims_ = dims;
        return f;
    }

    int resolution() const { return resolution_; }
    double cell_size() const { return cell_; }
    Vec3 origin() const { return origin_; }  // lower corner of cell (0,0,0)
    const std::array<int32_t, 3>& dims() const { return dims_; }
    int64_t cell_count() const { return int64_t(dims_[0]) * dims_[1] * dims_[2]; }

    // The cell holding `p`, clamped into the lattice (origins on the upper faces belong to the
    // last cell).
    Coord cell_of(Vec3 p) const {
        const double q[3] = {(p.x - origin_.x) / cell_, (p.y - origin_.y) / cell_,
                             (p.z - origin_.z) / cell_};
        Coord c;
        for (int a = 0; a < 3; ++a) c[a] = std::clamp(int32_t(std::floor(q[a])), 0, dims_[a] - 1);
        return c;
    }
    bool contains(const Coord& c) const {
        return c[0] >= 0 && c[1] >= 0 && c[2] >= 0 && c[0] < dims_[0] && c[1] < dims_[1] &&
               c[2] < dims_[2];
    }
    int64_t linear(const Coord& c) const {
        return (int64_t(c[2]) * dims_[1] + c[1]) * dims_[0] + c[0];
    }
    Coord coord(int64_t linear) const {
        return {int32_t(linear % dims_[0]), int32_t(linear / dims_[0] % dims_[1]),
                int32_t(linear / (int64_t(dims_[0]) * dims_[1]))};
    }
    Vec3 cell_lower(const Coord& c) const {
        return {origin_.x + c[0] * cell_, origin_.y + c[1] * cell_, origin_.z + c[2] * cell_};
    }
    Vec3 cell_centre(const Coord& c) const {
        return cell_lower(c) + Vec3{0.5 * cell_, 0.5 * cell_, 0.5 * cell_};
    }

private:
    int resolution_ = 0;
    double cell_ = 0;
    Vec3 origin_;
    std::array<int32_t, 3> dims_{0, 0, 0};
};

}  // namespace rayset::lightmodel
