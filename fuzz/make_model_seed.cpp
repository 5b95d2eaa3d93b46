// Writes a small, complete light-model file, the seed of fuzz_model (scripts/fuzz.sh runs it):
// write_model() of a model made here by hand, since building one from rays takes Embree and
// Ceres, which a fuzz tree does not build. It reads the file back, so that a seed the reader
// refuses (and the fuzzer would start from nothing) fails here.
// Usage: fuzz_model_seed OUT.vdb
#include "core/error.h"
#include "lightmodel/model_file.h"

#include <cstdio>
#include <map>

using namespace rayset;
using namespace rayset::lightmodel;

namespace {

// A 2 x 2 x 1 mm block: density voxels 4 x 4 x 1, flux cells 2 x 2 x 1, one intensity cell
// with one diagram, two spheres.
LightModel small_model() {
    LightModel m;
    m.source = {"synthetic.tm25ray", "tm25", 1000, 1.0, 683.0, "mm"};
    Box box;
    box.extend({-1, -1, 0});
    box.extend({1, 1, 1});
    m.density_frame = LatticeFrame(box, 4);
    m.flux_frame = LatticeFrame(box, 2);
    m.intensity_frame = LatticeFrame(box, 1);

    GoniometricDiagram diagram(4, 2);
    diagram.accumulate({0, 0, 1}, 1);
    diagram.accumulate({0.6, 0, 0.8}, 0.5);
    diagram.finalize();
    m.diagrams = {diagram};
    m.diagram_cells = {{0, 0, 0}};

    // Each density voxel goes to the flux cell holding its centre; cells in linear order, as a
    // build groups them.
    std::map<int64_t, std::vector<Coord>> grouped;
    const auto& dims = m.density_frame.dims();
    for (int32_t x = 0; x < dims[0]; ++x)
        for (int32_t y = 0; y < dims[1]; ++y)
            for (int32_t z = 0; z < dims[2]; ++z) {
                const Coord voxel{x, y, z};
                const Coord cell = m.flux_frame.cell_of(m.density_frame.cell_centre(voxel));
                grouped[m.flux_frame.linear(cell)].push_back(voxel);
            }
    for (const auto& [linear, voxels] : grouped) {
        FluxCell cell;
        cell.coord = m.flux_frame.cell_of(m.density_frame.cell_centre(voxels.front()));
        cell.flux = 0.25;
        cell.luminous = 170;
        cell.intensity_cell = 0;
        cell.first_voxel = uint32_t(m.voxels.size());
        cell.voxel_count = uint32_t(voxels.size());
        cell.visible_fraction = 0.9;
        m.flux_cells.push_back(cell);
        for (const Coord& v : voxels) {
            m.voxels.push_back(v);
            m.voxel_density.push_back(3);
        }
    }
    m.boundary_voxels = {m.voxels.front(), m.voxels.back()};
    m.spectra.assign(m.flux_cells.size() * size_t(m.bins.count), 0.f);
    for (size_t c = 0; c < m.flux_cells.size(); ++c) m.spectra[c * size_t(m.bins.count) + 7] = 1;
    m.spheres = {{0, 0, 0.5f, 0.9f}, {0.5f, 0.5f, 0.5f, 0.3f}};
    return m;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: fuzz_model_seed OUT.vdb\n");
        return 2;
    }
    try {
        write_model(small_model(), argv[1]);
        read_model(argv[1]);
    } catch (const Error& e) {
        std::fprintf(stderr, "fuzz_model_seed: %s\n", e.what());
        return 1;
    }
    return 0;
}
