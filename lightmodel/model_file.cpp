#include "lightmodel/model_file.h"

#include "converters/rays/io.h"
#include "core/error.h"
#include "lightmodel/vdb_file.h"

#include <fmt/format.h>
#include <openvdb/openvdb.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>

namespace rayset::lightmodel {

namespace {

// The grids' names.
namespace grid {
constexpr char density[] = "density", boundary[] = "boundary", flux[] = "flux",
               luminous[] = "luminous", visible_fraction[] = "visible_fraction",
               spectra[] = "spectra", intensity_cell[] = "intensity_cell", diagrams[] = "diagrams",
               spheres[] = "spheres";
}  // namespace grid

// Index space = lattice cells, voxel centres at cell centres (as DensityLattice does).
openvdb::math::Transform::Ptr frame_transform(const LatticeFrame& frame) {
    auto t = openvdb::math::Transform::createLinearTransform(frame.cell_size());
    const Vec3 o = frame.origin();
    const double half = 0.5 * frame.cell_size();
    t->postTranslate(openvdb::Vec3d(o.x + half, o.y + half, o.z + half));
    return t;
}

std::string frame_text(const LatticeFrame& f) {
    char buf[256];
    std::snprintf(buf, sizeof buf, "%d %.17g %.17g %.17g %.17g %d %d %d", f.resolution(),
                  f.origin().x, f.origin().y, f.origin().z, f.cell_size(), f.dims()[0], f.dims()[1],
                  f.dims()[2]);
    return buf;
}

LatticeFrame parse_frame(const std::string& text, const std::string& path,
                         const std::string& name) {
    std::istringstream in(text);
    int resolution = 0;
    Vec3 origin;
    double cell = 0;
    std::array<int32_t, 3> dims{};
    if (!(in >> resolution >> origin.x >> origin.y >> origin.z >> cell >> dims[0] >> dims[1] >>
          dims[2]) ||
        cell <= 0 || dims[0] <= 0 || dims[1] <= 0 || dims[2] <= 0)
        throw Error(path + ": metadata '" + name + "' is not a lattice frame: '" + text + "'");
    return LatticeFrame::from_parts(resolution, origin, cell, dims);
}

openvdb::Coord vdb(const Coord& c) { return openvdb::Coord(c[0], c[1], c[2]); }

template <class GridT>
typename GridT::Ptr find_grid(const openvdb::GridPtrVecPtr& grids, const std::string& name,
                              const std::string& path) {
    for (const auto& g : *grids)
        if (g->getName() == name)
            if (auto typed = openvdb::gridPtrCast<GridT>(g)) return typed;
    throw Error(path + ": not a rayset model: grid '" + name +
                "' is missing (is this a model written by raymodel?)");
}

// A table stored as a grid: value (column, row, 0). Rows are numbered from 0 without gaps, and
// each row's columns too; a row may be empty only at the end.
openvdb::FloatGrid::Ptr table_grid(const char* name, const std::vector<std::vector<float>>& rows) {
    auto table = openvdb::FloatGrid::create(0.f);
    table->setName(name);
    auto accessor = table->getAccessor();
    for (size_t row = 0; row < rows.size(); ++row)
        for (size_t column = 0; column < rows[row].size(); ++column)
            accessor.setValue(openvdb::Coord(int(column), int(row), 0), rows[row][column]);
    return table;
}

// The rows of a table grid, checked: a corrupt file's coordinates must not size what is read.
std::vector<std::vector<float>> read_table(const openvdb::FloatGrid& table,
                                           const std::string& path) {
    const std::string where = path + ": grid '" + table.getName() + "' ";
    if (table.tree().activeTileCount() != 0) throw Error(where + "is not a table (it has tiles)");
    struct Entry {
        openvdb::Coord at;
        float value;
    };
    std::vector<Entry> entries;
    for (auto it = table.cbeginValueOn(); it; ++it) entries.push_back({it.getCoord(), *it});
    std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
        return std::make_pair(a.at.y(), a.at.x()) < std::make_pair(b.at.y(), b.at.x());
    });
    auto voxel = [](const openvdb::Coord& c) {
        return "(" + std::to_string(c.x()) + ", " + std::to_string(c.y()) + ", " +
               std::to_string(c.z()) + ")";
    };
    std::vector<std::vector<float>> rows;
    for (const Entry& e : entries) {
        if (e.at.z() != 0 || e.at.y() < 0 || size_t(e.at.y()) > rows.size())
            throw Error(where + "has a value outside its rows, at " + voxel(e.at));
        if (size_t(e.at.y()) == rows.size()) rows.emplace_back();
        std::vector<float>& row = rows[size_t(e.at.y())];
        if (e.at.x() < 0 || size_t(e.at.x()) != row.size())
            throw Error(where + "has a gap in row " + std::to_string(e.at.y()) + ", at " +
                        voxel(e.at));
        row.push_back(e.value);
    }
    return rows;
}

// The body: one table row (x, y, z, r) per sphere.
openvdb::FloatGrid::Ptr sphere_grid(const std::vector<Sphere>& spheres) {
    std::vector<std::vector<float>> rows;
    rows.reserve(spheres.size());
    for (const Sphere& s : spheres) rows.push_back({s.x, s.y, s.z, s.r});
    return table_grid(grid::spheres, rows);
}

std::vector<Sphere> read_spheres(const openvdb::FloatGrid& table, const std::string& path) {
    std::vector<Sphere> spheres;
    for (const std::vector<float>& row : read_table(table, path)) {
        if (row.size() != 4)
            throw Error(path + ": sphere " + std::to_string(spheres.size()) + " has " +
                        std::to_string(row.size()) + " numbers, not x y z r");
        const Sphere s{row[0], row[1], row[2], row[3]};
        if (!(std::isfinite(s.x) && std::isfinite(s.y) && std::isfinite(s.z) &&
              std::isfinite(s.r) && s.r > 0))
            throw Error(
                fmt::format("{}: sphere {} is ({}, {}, {}) of radius {}, where a centre is "
                            "finite and a radius finite and positive: the file is corrupt "
                            "(build the model again with raymodel build)",
                            path, spheres.size(), s.x, s.y, s.z, s.r));
        spheres.push_back(s);
    }
    return spheres;
}

// The file's metadata, described once for writing and reading: `io` is a MetadataWriter (with a
// const LightModel) or a MetadataReader (with a LightModel). The build options are one text of
// key=value pairs.
constexpr char kVersionKey[] = "rayset_model_version";

template <class Io, class Options>
void describe_options(Io& io, Options& o) {
    visit_model_options(o,
                        [&](const char* key, auto& value, const char*) { io.option(key, value); });
}

template <class Io, class Model>
void describe_metadata(Io& io, Model& model) {
    io.text("source_path", model.source.path);
    io.text("source_format", model.source.format);
    io.text("source_unit", model.source.unit);
    io.number("source_rays", model.source.rays);
    io.number("source_radiant_W", model.source.radiant);
    io.number("source_luminous_lm", model.source.luminous);
    io.text("flux_unit", model.flux_unit);
    io.frame("density_frame", model.density_frame);
    io.frame("flux_frame", model.flux_frame);
    io.frame("intensity_frame", model.intensity_frame);
    io.bins("spectral_bins_nm", model.bins);
    io.options("build_options", model.options);
}

struct MetadataWriter {
    explicit MetadataWriter(openvdb::MetaMap& meta) : meta(meta) {}
    openvdb::MetaMap& meta;
    std::string options_text;

    void text(const char* key, const std::string& value) {
        meta.insertMeta(key, openvdb::StringMetadata(value));
    }
    void number(const char* key, uint64_t value) {
        meta.insertMeta(key, openvdb::Int64Metadata(int64_t(value)));
    }
    void number(const char* key, double value) {
        meta.insertMeta(key, openvdb::DoubleMetadata(value));
    }
    void frame(const char* key, const LatticeFrame& value) { text(key, frame_text(value)); }
    void bins(const char* key, const SpectralBins& b) {
        meta.insertMeta(key,
                        openvdb::Vec3DMetadata(openvdb::Vec3d(b.first_nm, b.width_nm, b.count)));
    }
    template <class T>
    void option(const char* key, T value) {
        options_text +=
            (options_text.empty() ? "" : " ") + std::string(key) + "=" + std::to_string(value);
    }
    void option(const char* key, DiagramSmoothing value) { option(key, int(value)); }
    void options(const char* key, const ModelOptions& o) {
        options_text.clear();
        describe_options(*this, o);
        text(key, options_text);
    }
};

// Texts, frames and the options are required; the numbers and bins keep their defaults when
// missing (files written before them).
struct MetadataReader {
    MetadataReader(const openvdb::MetaMap& meta, const std::string& path)
        : meta(meta), path(path) {}
    const openvdb::MetaMap& meta;
    const std::string& path;
    std::map<std::string, long long> option_values;

    void text(const char* key, std::string& value) {
        auto m = meta.getMetadata<openvdb::StringMetadata>(key);
        if (!m) throw Error(path + ": not a rayset model: metadata '" + key + "' is missing");
        value = m->value();
    }
    void number(const char* key, uint64_t& value) {
        if (auto m = meta.getMetadata<openvdb::Int64Metadata>(key)) value = uint64_t(m->value());
    }
    void number(const char* key, double& value) {
        if (auto m = meta.getMetadata<openvdb::DoubleMetadata>(key)) value = m->value();
    }
    void frame(const char* key, LatticeFrame& value) {
        std::string t;
        text(key, t);
        value = parse_frame(t, path, key);
    }
    // Bins as a build makes them (SpectralBins::count_covering), which also bounds the
    // per-cell spectra read for them.
    void bins(const char* key, SpectralBins& b) {
        auto m = meta.getMetadata<openvdb::Vec3DMetadata>(key);
        if (!m) return;
        const double first = m->value().x(), width = m->value().y(), count = m->value().z();
        const int covering = SpectralBins::count_covering(width);
        if (!std::isfinite(first) || covering == 0 || count != covering) {
            std::ostringstream text;
            text << first << " " << width << " " << count;
            throw Error(path + ": metadata '" + key + "' is '" + text.str() +
                        "': expected the first bin (nm), a positive width (nm) and the number of "
                        "bins of that width over the 400 nm from 380 to 780");
        }
        b.first_nm = first;
        b.width_nm = width;
        b.count = int(count);
    }
    template <class T>
    void option(const char* key, T& value) {
        if (auto found = option_values.find(key); found != option_values.end())
            value = T(found->second);
    }
    void option(const char* key, DiagramSmoothing& value) {
        const auto found = option_values.find(key);
        if (found == option_values.end()) return;
        if (found->second != int(DiagramSmoothing::none) &&
            found->second != int(DiagramSmoothing::automatic))
            throw Error(path + ": metadata 'build_options' holds '" + key + "=" +
                        std::to_string(found->second) + "': expected 0 (none) or 1 (auto)");
        value = DiagramSmoothing(found->second);
    }
    void options(const char* key, ModelOptions& o) {
        std::string t;
        text(key, t);
        std::istringstream in(t);
        for (std::string kv; in >> kv;) {
            const auto eq = kv.find('=');
            long long value = 0;
            bool whole_number = eq != std::string::npos && eq > 0;
            if (whole_number) {
                const char* end = kv.data() + kv.size();
                const auto [stop, error] = std::from_chars(kv.data() + eq + 1, end, value);
                whole_number = error == std::errc() && stop == end;
            }
            if (!whole_number)
                throw Error(path + ": metadata '" + key + "' holds '" + kv +
                            "': expected name=integer pairs separated by spaces");
            option_values[kv.substr(0, eq)] = value;
        }
        describe_options(*this, o);
    }
};

// The lattices of the density frame: ray counts of the occupied voxels, the boundary voxels.
void add_density_grids(const LightModel& model, openvdb::GridPtrVec& grids) {
    auto density = openvdb::FloatGrid::create(0.f);
    density->setName(grid::density);
    density->setTransform(frame_transform(model.density_frame));
    density->setGridClass(openvdb::GRID_FOG_VOLUME);
    auto counts = density->getAccessor();
    for (size_t v = 0; v < model.voxels.size(); ++v)
        counts.setValue(vdb(model.voxels[v]), model.voxel_density[v]);
    grids.push_back(density);

    // Int32, not bool: OpenVDB reads a bool from whatever byte a corrupt file holds, which is
    // undefined behaviour.
    auto boundary = openvdb::Int32Grid::create(0);
    boundary->setName(grid::boundary);
    boundary->setTransform(frame_transform(model.density_frame));
    auto flags = boundary->getAccessor();
    for (const Coord& c : model.boundary_voxels) flags.setValue(vdb(c), 1);
    grids.push_back(boundary);
}

// The flux cells' radiant (or luminous) and luminous flux and visible fractions, and their
// spectra as an index-space table: voxel (cell, bin, 0).
void add_flux_grids(const LightModel& model, openvdb::GridPtrVec& grids) {
    auto flux = openvdb::DoubleGrid::create(0.0);
    auto luminous = openvdb::DoubleGrid::create(0.0);
    auto visible = openvdb::FloatGrid::create(1.f);
    flux->setName(grid::flux);
    luminous->setName(grid::luminous);
    visible->setName(grid::visible_fraction);
    for (const openvdb::GridBase::Ptr& g :
         {openvdb::GridBase::Ptr(flux), openvdb::GridBase::Ptr(luminous),
          openvdb::GridBase::Ptr(visible)}) {
        g->setTransform(frame_transform(model.flux_frame));
        grids.push_back(g);
    }
    auto fa = flux->getAccessor();
    auto la = luminous->getAccessor();
    auto va = visible->getAccessor();
    for (const FluxCell& c : model.flux_cells) {
        fa.setValue(vdb(c.coord), c.flux);
        la.setValue(vdb(c.coord), c.luminous);
        va.setValue(vdb(c.coord), float(c.visible_fraction));
    }

    auto spectra = openvdb::FloatGrid::create(0.f);
    spectra->setName(grid::spectra);
    auto sa = spectra->getAccessor();
    for (size_t c = 0; c < model.flux_cells.size(); ++c)
        for (int b = 0; b < model.bins.count; ++b)
            sa.setValue(openvdb::Coord(int(c), b, 0),
                        model.spectra[c * size_t(model.bins.count) + size_t(b)]);
    grids.push_back(spectra);
}

// Each intensity cell's diagram number, and the diagrams as an index-space table: voxel
// (a, b, diagram).
void add_diagram_grids(const LightModel& model, openvdb::GridPtrVec& grids) {
    auto intensity_cell = openvdb::Int32Grid::create(-1);
    intensity_cell->setName(grid::intensity_cell);
    intensity_cell->setTransform(frame_transform(model.intensity_frame));
    auto ia = intensity_cell->getAccessor();
    std::vector<std::vector<float>> rows;
    for (size_t k = 0; k < model.diagrams.size(); ++k) {
        ia.setValue(vdb(model.diagram_cells[k]), int32_t(k));
        rows.push_back(model.diagrams[k].serialize());
    }
    grids.push_back(intensity_cell);
    grids.push_back(table_grid(grid::diagrams, rows));
}

// The grid types of a model: plain trees, read only after the version is known.
const VdbGridTypes kModelGridTypes = {openvdb::FloatGrid::gridType(),
                                      openvdb::DoubleGrid::gridType(),
                                      openvdb::Int32Grid::gridType()};

void check_model_version(const openvdb::MetaMap& meta, const std::string& path) {
    auto version = meta.getMetadata<openvdb::Int32Metadata>(kVersionKey);
    if (!version) throw Error(path + ": not a rayset model (no " + kVersionKey + " metadata)");
    if (version->value() != kModelVersion)
        throw Error(path + ": model version " + std::to_string(version->value()) +
                    ", this raymodel reads version " + std::to_string(kModelVersion) +
                    ": rebuild the model with raymodel build");
}

// Diagrams, in index order, and the intensity cell of each.
void read_diagrams(const VdbFile& file, const std::string& path, LightModel& model) {
    auto intensity_cell = find_grid<openvdb::Int32Grid>(file.grids, grid::intensity_cell, path);
    const std::vector<std::vector<float>> rows =
        read_table(*find_grid<openvdb::FloatGrid>(file.grids, grid::diagrams, path), path);
    model.diagram_cells.resize(rows.size());
    for (auto it = intensity_cell->cbeginValueOn(); it; ++it) {
        if (*it < 0 || size_t(*it) >= rows.size())
            throw Error(path + ": intensity_cell names a missing diagram");
        model.diagram_cells[size_t(*it)] = {it.getCoord().x(), it.getCoord().y(),
                                            it.getCoord().z()};
    }
    for (const auto& data : rows) {
        try {
            model.diagrams.push_back(GoniometricDiagram::deserialize(data));
        } catch (const std::exception& e) {
            throw Error(path + ": a goniometric diagram is malformed: " + e.what());
        }
    }
}

// A cell's values as a build writes them: a corrupt one would be sampled as light (a negative
// or NaN flux draws nonsense in every render).
void check_flux_cell(const FluxCell& c, const std::string& path) {
    const auto refuse = [&](const char* what, double value, const char* rule) {
        throw Error(
            fmt::format("{}: the flux cell at ({}, {}, {}) holds {} {}, where {}: the "
                        "file is corrupt (build the model again with raymodel build)",
                        path, c.coord[0], c.coord[1], c.coord[2], what, value, rule));
    };
    if (!(std::isfinite(c.flux) && c.flux >= 0))
        refuse("flux", c.flux, "a flux is finite and not negative");
    if (!(std::isnan(c.luminous) || (std::isfinite(c.luminous) && c.luminous >= 0)))
        refuse("luminous flux", c.luminous,
               "a luminous flux is finite and not negative (or NaN, unknown)");
    if (!(c.visible_fraction >= 0 && c.visible_fraction <= 1))
        refuse("visible fraction", c.visible_fraction, "a fraction is between 0 and 1");
}

// Flux cells in the order of their linear index, as the build made them; returns the index of
// each cell by its linear index.
std::map<int64_t, size_t> read_flux_cells(const VdbFile& file, const std::string& path,
                                          LightModel& model) {
    auto flux = find_grid<openvdb::DoubleGrid>(file.grids, grid::flux, path);
    auto la = find_grid<openvdb::DoubleGrid>(file.grids, grid::luminous, path)->getConstAccessor();
    auto va =
        find_grid<openvdb::FloatGrid>(file.grids, grid::visible_fraction, path)->getConstAccessor();
    std::vector<std::pair<int64_t, FluxCell>> cells;
    for (auto it = flux->cbeginValueOn(); it; ++it) {
        FluxCell c;
        c.coord = {it.getCoord().x(), it.getCoord().y(), it.getCoord().z()};
        c.flux = *it;
        c.luminous = la.getValue(it.getCoord());
        c.visible_fraction = va.getValue(it.getCoord());
        check_flux_cell(c, path);
        cells.emplace_back(model.flux_frame.linear(c.coord), c);
    }
    std::sort(cells.begin(), cells.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    std::map<int64_t, size_t> cell_index;
    for (const auto& [linear, cell] : cells) {
        cell_index[linear] = model.flux_cells.size();
        model.flux_cells.push_back(cell);
    }
    return cell_index;
}

// Voxels grouped by flux cell, in the density grid's order (as the build grouped them), and
// each flux cell's diagram.
void read_voxels(const VdbFile& file, const std::string& path,
                 const std::map<int64_t, size_t>& cell_index, LightModel& model) {
    auto density = find_grid<openvdb::FloatGrid>(file.grids, grid::density, path);
    auto ia =
        find_grid<openvdb::Int32Grid>(file.grids, grid::intensity_cell, path)->getConstAccessor();
    std::vector<std::vector<std::pair<Coord, float>>> grouped(model.flux_cells.size());
    for (auto it = density->cbeginValueOn(); it; ++it) {
        const Coord v{it.getCoord().x(), it.getCoord().y(), it.getCoord().z()};
        const Vec3 centre = model.density_frame.cell_centre(v);
        const auto found =
            cell_index.find(model.flux_frame.linear(model.flux_frame.cell_of(centre)));
        if (found == cell_index.end()) continue;  // a voxel whose rays carried no flux
        grouped[found->second].emplace_back(v, *it);
        FluxCell& cell = model.flux_cells[found->second];
        if (cell.intensity_cell < 0)
            cell.intensity_cell = ia.getValue(
                vdb(model.intensity_frame.cell_of(model.flux_frame.cell_centre(cell.coord))));
    }
    for (size_t c = 0; c < grouped.size(); ++c) {
        FluxCell& cell = model.flux_cells[c];
        if (grouped[c].empty() || cell.intensity_cell < 0 ||
            size_t(cell.intensity_cell) >= model.diagrams.size())
            throw Error(path + ": flux cell " + std::to_string(c) +
                        " has no voxels or no diagram: the file is inconsistent");
        cell.first_voxel = uint32_t(model.voxels.size());
        cell.voxel_count = uint32_t(grouped[c].size());
        for (const auto& [v, count] : grouped[c]) {
            model.voxels.push_back(v);
            model.voxel_density.push_back(count);
        }
    }
    auto boundary = find_grid<openvdb::Int32Grid>(file.grids, grid::boundary, path);
    for (auto it = boundary->cbeginValueOn(); it; ++it)
        model.boundary_voxels.push_back({it.getCoord().x(), it.getCoord().y(), it.getCoord().z()});
}

void read_spectra(const VdbFile& file, const std::string& path, LightModel& model) {
    auto spectra = find_grid<openvdb::FloatGrid>(file.grids, grid::spectra, path);
    model.spectra.assign(model.flux_cells.size() * size_t(model.bins.count), 0.f);
    for (auto it = spectra->cbeginValueOn(); it; ++it) {
        const size_t c = size_t(it.getCoord().x()), b = size_t(it.getCoord().y());
        if (c < model.flux_cells.size() && b < size_t(model.bins.count))
            model.spectra[c * size_t(model.bins.count) + b] = *it;
    }
}

}  // namespace

void write_model(const LightModel& model, const std::string& path) {
    openvdb::GridPtrVec grids;
    add_density_grids(model, grids);
    add_flux_grids(model, grids);
    add_diagram_grids(model, grids);
    grids.push_back(sphere_grid(model.spheres));

    openvdb::MetaMap meta;
    meta.insertMeta(kVersionKey, openvdb::Int32Metadata(kModelVersion));
    MetadataWriter writer(meta);
    describe_metadata(writer, model);

    write_vdb_file(path, grids, meta);
}

LightModel read_model(const std::string& path) {
    const VdbFile file = read_vdb_file(path, kModelGridTypes, [&](const openvdb::MetaMap& meta) {
        check_model_version(meta, path);
    });
    LightModel model;
    MetadataReader reader(*file.meta, path);
    describe_metadata(reader, model);
    read_diagrams(file, path, model);
    read_voxels(file, path, read_flux_cells(file, path, model), model);
    read_spectra(file, path, model);
    model.spheres =
        read_spheres(*find_grid<openvdb::FloatGrid>(file.grids, grid::spheres, path), path);
    return model;
}

}  // namespace rayset::lightmodel
