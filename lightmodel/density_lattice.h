// The density lattice: how many ray origins (or how much weight) fell in each cell of a
// LatticeFrame, held sparsely in OpenVDB, and the boundary cells of the occupied region, where
// the body's spheres go.
//
// Index space = lattice cells: voxel (i,j,k) of the grid is cell (i,j,k) of the frame, and the
// grid's transform (voxel size = cell size, voxel centres at the cell centres) maps world
// positions in mm to the cell holding them, so the grid stands alone in a .vdb file.
//
// Accumulation runs in double precision (a float count stops growing at 2^24 rays in one cell,
// which a point-like source reaches); grid() hands out the float copy named "density".
// add() is not thread-safe: a parallel build gives each thread its own lattice over the same
// frame (tbb::enumerable_thread_specific) and merges them with merge().
#pragma once

#include "lightmodel/lattice.h"

#include <openvdb/openvdb.h>

#include <cstdint>
#include <vector>

namespace rayset::lightmodel {

// Lattice resolution for a source of `ray_count` rays: N = clamp(round(sqrt(R / 64)), 8,
// max_resolution). A surface source of R rays at resolution N occupies about c N^2 cells (c of
// order 1: pi/4 for a disk seen along its axis, pi for a sphere), so the typical occupied cell
// receives R / (c N^2) = 64 / c rays: a few dozen, enough to sample the cell's origins for the
// sphere fit (64 by default) and to tell its density from its neighbours' to ~15%. The paper's
// 128^3 is reached from about 1 million rays on.
int adapted_resolution(uint64_t ray_count, int max_resolution = 128);

class DensityLattice {
public:
    explicit DensityLattice(const LatticeFrame& frame);
    // A lattice read back from a model file: `grid` as grid() wrote it.
    DensityLattice(const LatticeFrame& frame, const openvdb::FloatGrid& grid);

    const LatticeFrame& frame() const { return frame_; }

    // Counts each point once (origins outside the frame go to the nearest cell, as
    // LatticeFrame::cell_of does); `weights`, when given, holds one weight per point instead.
    void add(const std::vector<Vec3>& points);
    void add(const Vec3* points, size_t count, const float* weights = nullptr);
    // Adds another lattice over the same frame (the per-thread lattices of a parallel build);
    // `other` is left empty.
    void merge(DensityLattice& other);

    double count(const Coord& cell) const;
    double total() const;
    uint64_t occupied_cell_count() const;
    // Occupied cells with at least one of their 6 face neighbours empty or outside the lattice,
    // in the order of the lattice's linear index (x fastest), so builds are reproducible.
    std::vector<Coord> boundary_cells() const;

    // The counts as a FloatGrid named "density" (active voxels = occupied cells), a new grid on
    // each call.
    openvdb::FloatGrid::Ptr grid() const;

private:
    openvdb::math::Transform::Ptr transform() const;

    LatticeFrame frame_;
    openvdb::DoubleGrid::Ptr counts_;
};

}  // namespace rayset::lightmodel
