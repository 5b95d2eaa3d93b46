// A goniometric diagram: the probability density D(w) (sr^-1, integral over the sphere = 1) of
// the directions of the light leaving one cell of the intensity lattice.
//
// Grid: u = cos(theta) (theta from +z) and the azimuth phi, where dOmega = du dphi, so the
// `bands` equal bands of u in [-1, 1] times the `sectors` equal sectors of phi are cells of
// equal solid angle 4 pi / (bands sectors). `bands` is even, so the horizon u = 0 is a grid line.
//
// Density: piecewise bilinear in (u, phi) through the cell centres, whose values are the cells'
// histogram densities (weight / solid angle): each patch joins four neighbouring centres,
// periodic in phi. In u the centres' rows are closed by three kinds of rows of nodes:
//   - the poles u = +-1: one value for all phi, the linear extrapolation of the two nearest
//     rings' mean densities (a density smooth on the sphere has ring means smooth in u, and the
//     mean cancels the azimuthal terms that a lobe off the axis gives near the pole);
//   - the horizon u = 0, per sector: where the cells on both sides next to it hold light, the
//     ordinary interpolation between their centres; where one of them is dark, the linear
//     extrapolation of the two nearest centres on each side separately, so the density jumps
//     at u = 0 and the cut-off of a planar emitter stays sharp instead of being blurred over a
//     band (the dark side's extrapolation is 0).
// Extrapolated nodes are clamped at >= 0. A density linear in u on each side of the horizon (a
// Lambertian emitter) is then reproduced without bias. The nodes are scaled so the density
// integrates to 1, and sample() draws exactly in proportion to pdf().
//
// Life cycle: accumulate() / merge() any number of times, finalize(), then query. A diagram
// with no weight is *empty*: pdf() is 0 everywhere and sample() throws std::logic_error (there
// is no light to draw a direction of). Queries on a diagram changed since its last finalize()
// throw std::logic_error.
#pragma once

#include "core/alias_table.h"
#include "lightmodel/direction_map.h"

#include <vector>

namespace rayset::lightmodel {

struct DirectionSample {
    Vec3 direction;
    double pdf = 0;  // sr^-1, equal to GoniometricDiagram::pdf(direction) up to rounding
};

class GoniometricDiagram {
public:
    static constexpr int kDefaultBands = 40;
    static constexpr int kDefaultSectors = 12;

    // `bands` even and >= 2, `sectors` >= 1; throws std::invalid_argument otherwise.
    explicit GoniometricDiagram(int bands = kDefaultBands, int sectors = kDefaultSectors);

    int bands() const { return bands_; }
    int sectors() const { return sectors_; }
    int cell_count() const { return bands_ * sectors_; }
    double cell_solid_angle() const;  // sr, the same for every cell

    // Building. `w` a unit vector, `weight` finite and >= 0 (typically a ray's flux).
    void accumulate(Vec3 w, double weight);
    // Adds `other`'s histogram and weight to this one (same grid; both must still hold their
    // histograms, i.e. not be deserialised): the diagram of the union of their rays.
    void merge(const GoniometricDiagram& other);
    // Turns the histogram into the density described above.
    void finalize();

    double total_weight() const { return total_weight_; }
    // Weight accumulated per cell, index band * sectors + sector (cell_of()).
    const std::vector<double>& histogram() const { return histogram_; }
    bool has_histogram() const { return !histogram_.empty(); }

    // Queries (after finalize()).
    bool empty() const;
    double pdf(Vec3 w) const;  // sr^-1
    // Cell of a direction: band * sectors + sector, band 0 at u = -1, sector 0 from phi = 0.
    // u = 0 belongs to the band above the horizon.
    int cell_of(Vec3 w) const;
    double bin_average(int cell) const;  // exact mean of the density over the cell, sr^-1
    // `u` uniform in [0,1)^2. Picks a patch in proportion to its integral, then inverts the
    // bilinear density inside it: marginal in phi (linear), then conditional in u (linear).
    DirectionSample sample(Vec2 u) const;

    // Storage as a flat float array {bands, sectors, total weight, bands * sectors cell-centre
    // densities (sr^-1, index as cell_of)}; the derived nodes are rebuilt by the same rules.
    // The histogram is not stored, so a deserialised diagram answers queries but cannot
    // accumulate or merge. The nodes are kept in single precision, the file's, under one
    // normalising factor in double: pdf() and sample() stay consistent and integrate to 1 to
    // double precision, and a diagram read back answers exactly as the one written. Throws
    // std::invalid_argument on malformed data.
    std::vector<float> serialize() const;
    static GoniometricDiagram deserialize(const std::vector<float>& data);

    // A final diagram from densities (sr^-1, >= 0, index as cell_of) at the cells' centres, as
    // a smoothed estimate gives them; nodes and normalisation as for a histogram's. Like a
    // deserialised one it answers queries but cannot accumulate. Throws std::invalid_argument
    // for a bad grid or density.
    static GoniometricDiagram from_densities(int bands, int sectors, double total_weight,
                                             const std::vector<double>& centres);
    // The unit direction at the centre of cell `cell`.
    Vec3 cell_centre(int cell) const;

private:
    // Rows of nodes in increasing u: south pole, centres of the southern bands, horizon seen
    // from below, horizon seen from above, centres of the northern bands, north pole.
    int row_count() const { return bands_ + 4; }
    int centre_row(int band) const { return band < bands_ / 2 ? band + 1 : band + 3; }
    double row_u(int row) const { return row_u_[size_t(row)]; }
    int band_of(double u) const;
    int sector_of(double phi) const;
    double node(int row, int column) const { return nodes_[size_t(row) * sectors_ + column]; }
    float& stored_node(int row, int column) { return nodes_[size_t(row) * sectors_ + column]; }
    // Fills the centre rows from `centres` (index as cell_of) and derives pole and horizon rows.
    void build_nodes(const std::vector<double>& centres);
    // Scales the nodes so the density integrates to 1 and builds the patches' alias table.
    void normalise_nodes();
    // The density at (u, phi), phi in [0, 2 pi).
    double density(double u, double phi) const;
    void require_finalized() const;

    int bands_, sectors_;
    std::vector<double> histogram_;
    double total_weight_ = 0;
    bool finalized_ = false;
    // row_count() x sectors, node (row, column) at the sector's centre; single precision, as the
    // file stores the centres (half the memory a light sample's lookup reads), the density being
    // scale_ times them.
    std::vector<float> nodes_;
    double scale_ = 0;
    AliasTable patches_;         // the (row_count() - 1) x sectors patches by mass; empty if empty
    std::vector<double> row_u_;  // u of each row
};

}  // namespace rayset::lightmodel
