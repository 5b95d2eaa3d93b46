// Emitted-light colour (see colour.h).
#include "lightmodel/colour.h"

#include <algorithm>
#include <cmath>

namespace rayset::lightmodel {

namespace {

// One lobe of the fit: a Gaussian with different widths left and right of its peak.
double lobe(double wavelength, double peak, double width_below, double width_above) {
    const double t = (wavelength - peak) / (wavelength < peak ? width_below : width_above);
    return std::exp(-0.5 * t * t);
}

// Efficacy of a cell that says nothing about its luminous flux.
double default_efficacy(const LightModel& model) {
    return model.flux_unit == "lm" ? 1.0 : kRgbLumensPerWatt;
}

}  // namespace

Xyz colour_matching(double l) {
    return {1.056 * lobe(l, 599.8, 37.9, 31.0) + 0.362 * lobe(l, 442.0, 16.0, 26.7) -
                0.065 * lobe(l, 501.1, 20.4, 26.2),
            0.821 * lobe(l, 568.8, 46.9, 40.5) + 0.286 * lobe(l, 530.9, 16.3, 31.1),
            1.217 * lobe(l, 437.0, 11.8, 36.0) + 0.681 * lobe(l, 459.0, 26.0, 13.8)};
}

Xyz bin_colour_matching(const SpectralBins& bins, int bin) {
    const int steps = std::max(1, int(std::lround(bins.width_nm)));
    Xyz sum;
    for (int i = 0; i < steps; ++i) {
        const Xyz c = colour_matching(bins.first_nm + bin * bins.width_nm +
                                      (i + 0.5) * bins.width_nm / steps);
        sum.x += c.x, sum.y += c.y, sum.z += c.z;
    }
    return {sum.x / steps, sum.y / steps, sum.z / steps};
}

Rgb colour_per_flux(const Xyz& xyz, double efficacy) {
    const double scale = efficacy / kRgbLumensPerWatt;
    if (!(xyz.y > 0)) return {scale, scale, scale};
    Rgb c = to_linear_srgb({xyz.x / xyz.y, 1, xyz.z / xyz.y});  // Y = 1
    // Toward white (1, 1, 1), which has the same Y = 1, until the most negative channel is 0.
    const double lowest = std::min({c.red, c.green, c.blue});
    if (lowest < 0) {
        const double t = -lowest / (1 - lowest);
        c = {(1 - t) * c.red + t, (1 - t) * c.green + t, (1 - t) * c.blue + t};
    }
    const double y = luminance(c);  // 1 up to the rounding of the matrix
    return (scale / y) * c;
}

std::vector<Rgb> cell_colours(const LightModel& model) {
    std::vector<Xyz> bin_xyz(size_t(model.bins.count));
    for (int b = 0; b < model.bins.count; ++b)
        bin_xyz[size_t(b)] = bin_colour_matching(model.bins, b);
    std::vector<Rgb> colours;
    colours.reserve(model.flux_cells.size());
    for (size_t c = 0; c < model.flux_cells.size(); ++c) {
        const FluxCell& cell = model.flux_cells[c];
        Xyz xyz;
        for (int b = 0; b < model.bins.count && !model.spectra.empty(); ++b) {
            const double w = model.spectra[c * size_t(model.bins.count) + size_t(b)];
            xyz.x += w * bin_xyz[size_t(b)].x, xyz.y += w * bin_xyz[size_t(b)].y,
                xyz.z += w * bin_xyz[size_t(b)].z;
        }
        const double efficacy = std::isfinite(cell.luminous) && cell.flux > 0
                                    ? cell.luminous / cell.flux
                                    : default_efficacy(model);
        colours.push_back(colour_per_flux(xyz, efficacy));
    }
    return colours;
}

}  // namespace rayset::lightmodel
