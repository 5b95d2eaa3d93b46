// The body's balls by occupied voxel (see voxel_balls.h).
#include "lightmodel/voxel_balls.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace rayset::lightmodel {

namespace {

// Calls f(voxel, ball) for every occupied voxel whose cell the ball's box overlaps.
template <class F>
void for_each_listing(const LightModel& model,
                      const std::unordered_map<int64_t, uint32_t>& voxel_of, F&& f) {
    const LatticeFrame& frame = model.density_frame;
    for (uint32_t b = 0; b < model.spheres.size(); ++b) {
        const Sphere& s = model.spheres[b];
        const Coord lo = frame.cell_of({s.x - s.r, s.y - s.r, s.z - s.r});
        const Coord hi = frame.cell_of({s.x + s.r, s.y + s.r, s.z + s.r});
        for (int32_t z = lo[2]; z <= hi[2]; ++z)
            for (int32_t y = lo[1]; y <= hi[1]; ++y)
                for (int32_t x = lo[0]; x <= hi[0]; ++x) {
                    const auto it = voxel_of.find(frame.linear({x, y, z}));
                    if (it != voxel_of.end()) f(it->second, b);
                }
    }
}

}  // namespace

VoxelBalls::VoxelBalls(const LightModel& model) {
    const LatticeFrame& frame = model.density_frame;
    std::unordered_map<int64_t, uint32_t> voxel_of;
    voxel_of.reserve(model.voxels.size());
    for (uint32_t v = 0; v < model.voxels.size(); ++v) voxel_of[frame.linear(model.voxels[v])] = v;

    start_.assign(model.voxels.size() + 1, 0);
    for_each_listing(model, voxel_of, [&](uint32_t v, uint32_t) { ++start_[v + 1]; });
    for (size_t v = 1; v < start_.size(); ++v) start_[v] += start_[v - 1];
    std::vector<uint32_t> listed(start_.back());
    std::vector<uint32_t> fill(start_.begin(), start_.end() - 1);
    for_each_listing(model, voxel_of, [&](uint32_t v, uint32_t b) { listed[fill[v]++] = b; });

    balls_.resize(listed.size());
    for (uint32_t v = 0; v < model.voxels.size(); ++v) {
        const Vec3 centre = frame.cell_centre(model.voxels[v]);
        auto reach = [&](uint32_t b) {
            const Sphere& s = model.spheres[b];
            return length(centre_of(s) - centre) - s.r;
        };
        const auto first = listed.begin() + start_[v], last = listed.begin() + start_[v + 1];
        std::sort(first, last, [&](uint32_t a, uint32_t b) { return reach(a) < reach(b); });
        for (auto it = first; it != last; ++it)
            balls_[size_t(it - listed.begin())] = model.spheres[*it];
    }
}

bool VoxelBalls::ray_enters(uint32_t voxel, Vec3 origin, Vec3 dir, double t_max) const {
    double t0, t1;
    for (uint32_t k = start_[voxel]; k < start_[voxel + 1]; ++k)
        if (line_ball(balls_[k], origin, dir, t0, t1) && t0 >= 0 && t0 <= t_max) return true;
    return false;
}

}  // namespace rayset::lightmodel
