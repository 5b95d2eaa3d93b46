// EmissionVolume::traverse: a 3-D digital differential analyser (Amanatides & Woo 1987,
// "A Fast Voxel Traversal Algorithm for Ray Tracing") over the dense density lattice.
#pragma once

#include <cmath>
#include <limits>

namespace rayset::lightmodel {

template <class F>
void EmissionVolume::traverse(Vec3 origin, Vec3 dir, double tmin, double tmax, F&& f) const {
    const LatticeFrame& frame = model_.density_frame;
    const double h = frame.cell_size();
    const Vec3 lo = frame.origin();
    const auto& dims = frame.dims();
    const double o[3] = {(origin.x - lo.x) / h, (origin.y - lo.y) / h, (origin.z - lo.z) / h};
    const double d[3] = {dir.x / h, dir.y / h, dir.z / h};

    // Clip the segment to the lattice box (in cell units).
    double t0 = tmin, t1 = tmax;
    for (int a = 0; a < 3; ++a) {
        if (d[a] == 0) {
            if (o[a] < 0 || o[a] > dims[a]) return;
            continue;
        }
        double ta = (0 - o[a]) / d[a], tb = (dims[a] - o[a]) / d[a];
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
    }
    if (!(t0 < t1)) return;

    // A cell's exits are computed from its index, not accumulated step by step, so that every
    // traversal of a line finds the same boundaries wherever along it it starts.
    int cell[3], step[3];
    double inverse[3], exit_offset[3], next[3];
    const double inf = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a) {
        const double p = o[a] + t0 * d[a];
        cell[a] = std::clamp(int(std::floor(p)), 0, dims[a] - 1);
        step[a] = d[a] > 0 ? 1 : d[a] < 0 ? -1 : 0;
        inverse[a] = step[a] != 0 ? 1 / d[a] : 0;
        exit_offset[a] = (d[a] > 0 ? 1 : 0) - o[a];
        next[a] = step[a] != 0 ? (cell[a] + exit_offset[a]) * inverse[a] : inf;
    }
    double t = t0;
    while (t < t1) {
        const int a = next[0] < next[1] ? (next[0] < next[2] ? 0 : 2) : (next[1] < next[2] ? 1 : 2);
        const double t_exit = std::min(next[a], t1);
        const int32_t c = voxel_cell_[(int64_t(cell[2]) * dims[1] + cell[1]) * dims[0] + cell[0]];
        if (c >= 0 && t_exit > t) f(uint32_t(c), t, t_exit);
        t = t_exit;
        cell[a] += step[a];
        if (cell[a] < 0 || cell[a] >= dims[a]) return;
        next[a] = (cell[a] + exit_offset[a]) * inverse[a];
    }
}

}  // namespace rayset::lightmodel
