#include "viz/intensity_table.h"

#include "converters/colour/spectrum.h"

#include <cmath>
#include <filesystem>

namespace rayset::viz {

namespace {

std::string file_label(const std::string& path) {
    return std::filesystem::path(path).filename().string();
}

// The largest value on the stored grid and where it is.
void locate_maximum(IntensityTable& t) {
    const Photometry& p = t.photometry;
    t.max_intensity = -1;
    for (size_t h = 0; h < p.horizontal_deg.size(); ++h)
        for (size_t v = 0; v < p.vertical_deg.size(); ++v)
            if (p.candela[p.index(h, v)] > t.max_intensity) {
                t.max_intensity = p.candela[p.index(h, v)];
                t.max_c_deg = p.horizontal_deg[h];
                t.max_gamma_deg = p.vertical_deg[v];
            }
}

}  // namespace

IntensityTable intensity_of_rays(const std::string& path, FarFieldOptions options) {
    auto reader = open_rays(path);
    const bool luminous = PhotometricWeights(reader->header()).luminous_known();
    options.quantity = luminous ? FarFieldQuantity::photometric : FarFieldQuantity::radiometric;
    options.axis = PolarAxis::plus_z;
    FarField field = far_field(*reader, options);
    IntensityTable t;
    t.standard_error = field.photometry;
    for (size_t k = 0; k < field.variance.size(); ++k)
        t.standard_error->candela[k] = std::sqrt(field.variance[k]);
    t.photometry = std::move(field.photometry);
    t.unit = luminous ? "cd" : "W/sr";
    t.label = file_label(path);
    t.axis = 1;
    locate_maximum(t);
    return t;
}

IntensityTable intensity_of_photometry(const std::string& path) {
    IntensityTable t;
    t.photometry = read_photometry(path);
    if (t.photometry.type != PhotometricType::C)
        fail(path, "photometric type A or B has no C planes; rayview shows type C photometry only");
    t.unit = "cd";
    t.label = file_label(path);
    t.axis = -1;
    locate_maximum(t);
    return t;
}

}  // namespace rayset::viz
