// Density lattice: accumulation of origins into a sparse double grid, boundary cells, export.
#include "lightmodel/density_lattice.h"

#include <openvdb/tools/Composite.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rayset::lightmodel {

namespace {

void initialize_openvdb() {
    // Thread-safe once: a function-local static is initialised exactly once (C++11).
    static const bool initialized = (openvdb::initialize(), true);
    (void)initialized;
}

openvdb::Coord to_vdb(const Coord& c) { return openvdb::Coord(c[0], c[1], c[2]); }

}  // namespace

int adapted_resolution(uint64_t ray_count, int max_resolution) {
    if (max_resolution < 1)
        throw std::invalid_argument("adapted_resolution: max_resolution must be >= 1");
    const double n = std::round(std::sqrt(double(ray_count) / 64.0));
    const int lower = std::min(8, max_resolution);
    return int(std::clamp(n, double(lower), double(max_resolution)));
}

DensityLattice::DensityLattice(const LatticeFrame& frame) : frame_(frame) {
    initialize_openvdb();
    counts_ = openvdb::DoubleGrid::create(0.0);
    counts_->setTransform(transform());
}

DensityLattice::DensityLattice(const LatticeFrame& frame, const openvdb::FloatGrid& grid)
    : frame_(frame) {
    initialize_openvdb();
    counts_ =
        openvdb::DoubleGrid::create(openvdb::DoubleTree::Ptr(new openvdb::DoubleTree(grid.tree())));
    counts_->tree().voxelizeActiveTiles();  // a pruned file may hold tiles; cells are voxels here
    counts_->setTransform(transform());
}

openvdb::math::Transform::Ptr DensityLattice::transform() const {
    // OpenVDB puts voxel centres at integer index coordinates, so cell (0,0,0), whose lower
    // corner is the frame origin, has its centre at origin + h/2.
    const double h = frame_.cell_size();
    auto xform = openvdb::math::Transform::createLinearTransform(h);
    const Vec3 o = frame_.origin();
    xform->postTranslate(openvdb::Vec3d(o.x + 0.5 * h, o.y + 0.5 * h, o.z + 0.5 * h));
    return xform;
}

void DensityLattice::add(const std::vector<Vec3>& points) { add(points.data(), points.size()); }

void DensityLattice::add(const Vec3* points, size_t count, const float* weights) {
    auto accessor = counts_->getAccessor();
    for (size_t i = 0; i < count; ++i) {
        const double w = weights ? double(weights[i]) : 1.0;
        if (!(w > 0)) continue;  // a ray of no light does not make a cell occupied
        accessor.modifyValue(to_vdb(frame_.cell_of(points[i])), [w](double& v) { v += w; });
    }
}

void DensityLattice::merge(DensityLattice& other) {
    if (other.frame_.cell_size() != frame_.cell_size() || other.frame_.dims() != frame_.dims())
        throw std::invalid_argument("DensityLattice::merge: lattices over different frames");
    openvdb::tools::compSum(*counts_, *other.counts_);
}

double DensityLattice::count(const Coord& cell) const {
    return counts_->getConstAccessor().getValue(to_vdb(cell));
}

double DensityLattice::total() const {
    double sum = 0;
    for (auto it = counts_->cbeginValueOn(); it; ++it) sum += *it;
    return sum;
}

uint64_t DensityLattice::occupied_cell_count() const { return counts_->activeVoxelCount(); }

std::vector<Coord> DensityLattice::boundary_cells() const {
    static const int kNeighbours[6][3] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                          {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
    auto accessor = counts_->getConstAccessor();
    std::vector<Coord> cells;
    for (auto it = counts_->cbeginValueOn(); it; ++it) {
        const openvdb::Coord c = it.getCoord();
        for (const auto& n : kNeighbours) {
            const Coord neighbour{c.x() + n[0], c.y() + n[1], c.z() + n[2]};
            if (!frame_.contains(neighbour) || !accessor.isValueOn(to_vdb(neighbour))) {
                cells.push_back({c.x(), c.y(), c.z()});
                break;
            }
        }
    }
    std::sort(cells.begin(), cells.end(), [this](const Coord& a, const Coord& b) {
        return frame_.linear(a) < frame_.linear(b);
    });
    return cells;
}

openvdb::FloatGrid::Ptr DensityLattice::grid() const {
    auto grid = openvdb::FloatGrid::create(
        openvdb::FloatTree::Ptr(new openvdb::FloatTree(counts_->tree())));
    grid->setTransform(transform());
    grid->setName("density");
    grid->setGridClass(openvdb::GRID_UNKNOWN);
    return grid;
}

}  // namespace rayset::lightmodel
