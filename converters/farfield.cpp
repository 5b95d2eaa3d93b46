#include "converters/farfield.h"

#include "converters/error.h"
#include "converters/io.h"
#include "converters/spectrum.h"

#include <cmath>
#include <string>

namespace rayset {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kRadian = kPi / 180;

// A step divides `range` when the quotient is a whole number to rounding (2.5 into 180).
size_t divisions(double range, double step, const char* what) {
    const double q = range / step;
    const double whole = std::round(q);
    if (!(step > 0 && std::isfinite(step)) || std::abs(q - whole) > 1e-9 * q || whole > 1e6)
        throw Error(std::string("far field: the ") + what + " step " + format_double(step) +
                    " degrees must divide " + format_double(range) + " degrees");
    return size_t(whole);
}

}  // namespace

FarFieldGrid::FarFieldGrid(const FarFieldOptions& options)
    : c_step_(options.c_step_deg), gamma_step_(options.gamma_step_deg) {
    c_count_ = divisions(360, c_step_, "C");
    gamma_count_ = divisions(180, gamma_step_, "gamma") + 1;
}

double FarFieldGrid::gamma_low(size_t j) const { return j == 0 ? 0 : (double(j) - 0.5) * gamma_step_; }

double FarFieldGrid::gamma_high(size_t j) const {
    return j + 1 == gamma_count_ ? 180 : (double(j) + 0.5) * gamma_step_;
}

double FarFieldGrid::solid_angle(size_t j) const {
    // cos a - cos b = 2 sin((a+b)/2) sin((b-a)/2): no cancellation in the small polar cells.
    const double a = gamma_low(j) * kRadian, b = gamma_high(j) * kRadian;
    return c_step_ * kRadian * 2 * std::sin((a + b) / 2) * std::sin((b - a) / 2);
}

void FarFieldGrid::locate(double x, double y, double z, PolarAxis axis, size_t& i, size_t& j) const {
    const double polar = axis == PolarAxis::plus_z ? z : -z;
    const double gamma = std::atan2(std::hypot(x, y), polar) / kRadian;
    j = std::min(size_t(std::floor(gamma / gamma_step_ + 0.5)), gamma_count_ - 1);
    double c = std::atan2(y, x) / kRadian;
    if (c < 0) c += 360;
    i = size_t(std::floor(c / c_step_ + 0.5)) % c_count_;
}

FarField far_field(RayReader& reader, const FarFieldOptions& options) {
    const FarFieldGrid grid(options);
    const RayHeader& header = reader.header();
    const PhotometricWeights weights(header);
    const bool photometric = options.quantity == FarFieldQuantity::photometric;
    if (photometric && !weights.luminous_known())
        fail(reader.path(), "the rays carry neither luminous flux nor radiant flux with a spectrum, so their "
                            "luminous intensity is unknown; ask for a radiometric far field instead");
    if (!photometric && !weights.radiant_known())
        fail(reader.path(), "the rays carry neither radiant flux nor luminous flux with a spectrum, so their "
                            "radiant intensity is unknown; ask for a photometric far field instead");

    const size_t nc = grid.c_count(), ng = grid.gamma_count();
    std::vector<double> flux(nc * ng, 0), square(nc * ng, 0);
    RayChunk chunk;
    uint64_t rays = 0;
    while (reader.read(chunk)) {
        for (size_t k = 0; k < chunk.rays.size(); ++k) {
            const Ray& ray = chunk.rays[k];
            const double f = photometric ? weights.luminous(ray) : weights.radiant(ray);
            if (!std::isfinite(f))
                fail(reader.path(), "ray " + std::to_string(chunk.first_index + k + 1) + ": its " +
                                        (photometric ? "luminous" : "radiant") +
                                        " flux is unknown (no flux column for it and an unknown wavelength)");
            size_t i, j;
            grid.locate(ray.direction.x, ray.direction.y, ray.direction.z, options.axis, i, j);
            flux[i * ng + j] += f;
            square[i * ng + j] += f * f;
        }
        rays += chunk.rays.size();
        if (options.progress) options.progress(reader.progress());
    }

    FarField out;
    out.rays = rays;
    Photometry& p = out.photometry;
    p.type = PhotometricType::C;
    for (size_t j = 0; j < ng; ++j) p.vertical_deg.push_back(double(j) * grid.gamma_step_deg());
    for (size_t i = 0; i <= nc; ++i) p.horizontal_deg.push_back(double(i) * grid.c_step_deg());
    p.rated_lumens = -1;
    const size_t cells = (nc + 1) * ng;
    p.candela.resize(cells);
    out.flux.resize(cells);
    out.solid_angle.resize(cells);
    out.variance.resize(cells);
    for (size_t i = 0; i <= nc; ++i) {
        const size_t source = i % nc;  // the 360 plane repeats the 0 plane
        for (size_t j = 0; j < ng; ++j) {
            const double omega = grid.solid_angle(j);
            const size_t at = p.index(i, j);
            out.flux[at] = flux[source * ng + j];
            out.solid_angle[at] = omega;
            p.candela[at] = out.flux[at] / omega;
            out.variance[at] = square[source * ng + j] / (omega * omega);
            if (i < nc) out.total_flux += out.flux[at];
            if (p.candela[at] > out.max_intensity) {
                out.max_intensity = p.candela[at];
                out.max_c_deg = p.horizontal_deg[i];
                out.max_gamma_deg = p.vertical_deg[j];
            }
        }
    }

    p.keywords["TEST"] = "far field of " + reader.path();
    if (!header.text[1].empty()) p.keywords["MANUFAC"] = header.text[1];
    if (!header.text[0].empty()) p.keywords["LUMINAIRE"] = header.text[0];
    p.keywords["_RAYS"] = std::to_string(rays);
    p.keywords["_POLAR_AXIS"] = options.axis == PolarAxis::plus_z
                                    ? "gamma 0 is +z of the ray file; C0 is +x, C90 is +y"
                                    : "gamma 0 is -z of the ray file; C0 is +x, C90 is +y";
    if (!photometric) p.keywords["_RADIOMETRIC"] = "candela values are radiant intensities in W/sr";
    return out;
}

}  // namespace rayset
