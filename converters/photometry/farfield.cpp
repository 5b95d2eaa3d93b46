#include "converters/photometry/farfield.h"

#include "converters/colour/spectrum.h"
#include "converters/photometry/farfield_smoothing.h"
#include "converters/rays/io.h"
#include "core/error.h"
#include "core/geometry.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>

namespace rayset {

namespace {

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

double FarFieldGrid::gamma_low(size_t j) const {
    return j == 0 ? 0 : (double(j) - 0.5) * gamma_step_;
}

double FarFieldGrid::gamma_high(size_t j) const {
    return j + 1 == gamma_count_ ? 180 : (double(j) + 0.5) * gamma_step_;
}

double FarFieldGrid::solid_angle(size_t j) const {
    // cos a - cos b = 2 sin((a+b)/2) sin((b-a)/2): no cancellation in the small polar cells.
    const double a = gamma_low(j) * kRadiansPerDegree, b = gamma_high(j) * kRadiansPerDegree;
    return c_step_ * kRadiansPerDegree * 2 * std::sin((a + b) / 2) * std::sin((b - a) / 2);
}

void FarFieldGrid::locate(double x, double y, double z, PolarAxis axis, size_t& i,
                          size_t& j) const {
    const double polar = axis == PolarAxis::plus_z ? z : -z;
    const double gamma = std::atan2(std::hypot(x, y), polar) / kRadiansPerDegree;
    j = std::min(size_t(std::floor(gamma / gamma_step_ + 0.5)), gamma_count_ - 1);
    double c = std::atan2(y, x) / kRadiansPerDegree;
    if (c < 0) c += 360;
    i = size_t(std::floor(c / c_step_ + 0.5)) % c_count_;
}

namespace {

constexpr double kMinBandwidthDeg = kFarFieldResolution.min_sigma_deg / 2, kMaxBandwidthDeg = 45;
bool bandwidth_allowed(double degrees) {
    return degrees >= kMinBandwidthDeg && degrees <= kMaxBandwidthDeg;
}

}  // namespace

void parse_smoothing(const std::string& text, FarFieldOptions& options) {
    if (text == "auto") {
        options.smoothing = FarFieldSmoothing::automatic;
        return;
    }
    if (text == "none") {
        options.smoothing = FarFieldSmoothing::none;
        return;
    }
    char* end = nullptr;
    const double degrees = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || !bandwidth_allowed(degrees))
        throw Error("far field: smoothing '" + text +
                    "': expected auto, none or a bandwidth in degrees from " +
                    format_double(kMinBandwidthDeg) + " to " + format_double(kMaxBandwidthDeg));
    options.smoothing = FarFieldSmoothing::fixed;
    options.smoothing_deg = degrees;
}

namespace {

// The rays of `reader` binned into the grid's cells (flux and squared flux, C-major) and, for
// smoothing, into a direction histogram.
struct BinnedRays {
    std::vector<double> flux, square;
    DirectionHistogram directions;
    uint64_t rays = 0;
};

void bin_rays(RayReader& reader, const FarFieldGrid& grid, const FarFieldOptions& options,
              BinnedRays& out) {
    const PhotometricWeights weights(reader.header());
    const bool photometric = options.quantity == FarFieldQuantity::photometric;
    if (photometric && !weights.luminous_known())
        fail(reader.path(),
             "the rays carry neither luminous flux nor radiant flux with a spectrum, so their "
             "luminous intensity is unknown; ask for a radiometric far field instead");
    if (!photometric && !weights.radiant_known())
        fail(reader.path(),
             "the rays carry neither radiant flux nor luminous flux with a spectrum, so their "
             "radiant intensity is unknown; ask for a photometric far field instead");
    const size_t ng = grid.gamma_count();
    out.flux.assign(grid.c_count() * ng, 0);
    out.square.assign(grid.c_count() * ng, 0);
    const bool smoothing = options.smoothing != FarFieldSmoothing::none;
    const double polar_sign = options.axis == PolarAxis::plus_z ? 1 : -1;
    RayChunk chunk;
    while (reader.read(chunk)) {
        for (size_t k = 0; k < chunk.rays.size(); ++k) {
            const Ray& ray = chunk.rays[k];
            const double f = photometric ? weights.luminous(ray) : weights.radiant(ray);
            if (!std::isfinite(f))
                fail(reader.path(),
                     "ray " + std::to_string(chunk.first_index + k + 1) + ": its " +
                         (photometric ? "luminous" : "radiant") +
                         " flux is unknown (no flux column for it and an unknown wavelength)");
            size_t i, j;
            grid.locate(ray.direction.x, ray.direction.y, ray.direction.z, options.axis, i, j);
            out.flux[i * ng + j] += f;
            out.square[i * ng + j] += f * f;
            if (smoothing)
                out.directions.add(ray.direction.x, ray.direction.y, polar_sign * ray.direction.z,
                                   f);
        }
        out.rays += chunk.rays.size();
        if (options.progress) options.progress(reader.progress() * (smoothing ? 0.5 : 1.0));
    }
}

// Intensity and variance of each cell of the histogram, the polar caps pooled over C.
void histogram_values(const FarFieldGrid& grid, const BinnedRays& binned,
                      std::vector<double>& intensity, std::vector<double>& variance) {
    const size_t nc = grid.c_count(), ng = grid.gamma_count();
    intensity.assign(nc * ng, 0);
    variance.assign(nc * ng, 0);
    for (size_t j = 0; j < ng; ++j) {
        const bool cap = j == 0 || j + 1 == ng;
        double cap_flux = 0, cap_square = 0;
        if (cap)
            for (size_t i = 0; i < nc; ++i)
                cap_flux += binned.flux[i * ng + j], cap_square += binned.square[i * ng + j];
        const double omega = grid.solid_angle(j), cap_omega = omega * double(nc);
        for (size_t i = 0; i < nc; ++i) {
            const size_t at = i * ng + j;
            intensity[at] = cap ? cap_flux / cap_omega : binned.flux[at] / omega;
            variance[at] =
                cap ? cap_square / (cap_omega * cap_omega) : binned.square[at] / (omega * omega);
        }
    }
}

// Kernel estimates at the grid angles (C-major), on all cores; the poles evaluated once.
void smoothed_values(const FarFieldGrid& grid, const DirectionHistogram& directions,
                     const FarFieldOptions& options, std::vector<double>& intensity,
                     std::vector<double>& variance, std::vector<double>& sigma,
                     std::vector<char>& kind) {
    const size_t nc = grid.c_count(), ng = grid.gamma_count();
    intensity.assign(nc * ng, 0);
    variance.assign(nc * ng, 0);
    sigma.assign(nc * ng, 0);
    kind.assign(nc * ng, 0);
    auto at_node = [&](size_t i, size_t j) {
        const double gamma = double(j) * grid.gamma_step_deg() * kRadiansPerDegree,
                     c = double(i) * grid.c_step_deg() * kRadiansPerDegree;
        const double x = std::sin(gamma) * std::cos(c), y = std::sin(gamma) * std::sin(c),
                     polar = std::cos(gamma);
        return options.smoothing == FarFieldSmoothing::fixed
                   ? directions.at(x, y, polar, options.smoothing_deg)
                   : directions.adaptive(x, y, polar);
    };
    // The cell's mean of the estimate with the bandwidth chosen at its grid angle: Gauss-Legendre
    // in C and cos(gamma) (2 x 2 points; the polar caps 4 in C x 2), so that the values times the
    // cells' solid angles sum to the estimate's integral, as the histogram's sum to the rays' flux.
    auto estimate = [&](size_t i, size_t j) {
        DirectionHistogram::Estimate e = at_node(i, j);
        const double g0 = grid.gamma_low(j) * kRadiansPerDegree,
                     g1 = grid.gamma_high(j) * kRadiansPerDegree;
        const bool cap = j == 0 || j + 1 == ng;
        const double c_mid = cap ? kPi : double(i) * grid.c_step_deg() * kRadiansPerDegree;
        const double c_half = cap ? kPi : grid.c_step_deg() * kRadiansPerDegree / 2;
        const double mu0 = std::cos(g1), mu1 = std::cos(g0);
        const double node = 1 / std::sqrt(3.0);
        const int c_points = cap ? 4 : 2;
        double sum = 0;
        for (int a = 0; a < c_points; ++a) {
            // Cap: 4 equal C steps (the rule in C needs only to be exact for its few harmonics).
            const double c =
                cap ? (a + 0.5) * (2 * kPi / c_points) : c_mid + (a == 0 ? -node : node) * c_half;
            for (int b = 0; b < 2; ++b) {
                const double mu = (mu0 + mu1) / 2 + (b == 0 ? -node : node) * (mu1 - mu0) / 2;
                const double r = std::sqrt(std::max(0.0, 1 - mu * mu));
                sum += directions.at_kernel_of(r * std::cos(c), r * std::sin(c), mu, e).intensity;
            }
        }
        e.intensity = sum / (2 * c_points);
        return e;
    };
    auto store = [&](size_t at, const DirectionHistogram::Estimate& e) {
        intensity[at] = std::max(0.0, e.intensity);  // the twiced kernel dips below 0 in the dark
        variance[at] = e.standard_error * e.standard_error;
        sigma[at] = e.sigma_deg;
        kind[at] = char(e.kind);
    };
    const DirectionHistogram::Estimate north = estimate(0, 0), south = estimate(0, ng - 1);
    for (size_t i = 0; i < nc; ++i) store(i * ng, north), store(i * ng + ng - 1, south);

    std::atomic<size_t> next_plane{0}, planes_done{0};
    // Planes taken in turn by every thread; the calling thread alone reports progress.
    auto work = [&](bool report) {
        for (size_t i; (i = next_plane++) < nc;) {
            for (size_t j = 1; j + 1 < ng; ++j) store(i * ng + j, estimate(i, j));
            const size_t done = ++planes_done;
            if (report && options.progress) options.progress(0.5 + 0.5 * double(done) / double(nc));
        }
    };
    const size_t threads = std::max(1u, std::thread::hardware_concurrency());
    std::vector<std::thread> pool;
    for (size_t t = 1; t < threads; ++t) pool.emplace_back(work, false);
    work(true);
    for (std::thread& t : pool) t.join();
}

std::string smoothing_description(const FarFieldOptions& options, const std::vector<double>& sigma,
                                  const std::vector<char>& kind) {
    switch (options.smoothing) {
        case FarFieldSmoothing::none:
            return "none: each cell's flux over its solid angle, the polar caps pooled over C";
        case FarFieldSmoothing::fixed:
            return "kernel density, twiced von Mises-Fisher kernel, sigma " +
                   format_double(options.smoothing_deg) + " deg";
        case FarFieldSmoothing::automatic: break;
    }
    std::vector<double> sorted = sigma;
    std::sort(sorted.begin(), sorted.end());
    auto share = [&](DirectionHistogram::Kind k) {
        return 100 * double(std::count(kind.begin(), kind.end(), char(k))) / double(kind.size());
    };
    char text[320];
    std::snprintf(
        text, sizeof text,
        "kernel density (twiced von Mises-Fisher kernel), local log-quadratic fit or edge fit, "
        "chosen "
        "per direction with sigma by Goldenshluger-Lepski: sigma %.3g to %.3g deg, median %.3g; "
        "log-quadratic fits at %.0f%% and edge fits at %.0f%% of the directions",
        sorted.front(), sorted.back(), sorted[sorted.size() / 2],
        share(DirectionHistogram::Kind::log_quadratic), share(DirectionHistogram::Kind::edge));
    return text;
}

// The ratio that makes the estimate's total flux the rays'.
double flux_scale(const FarFieldGrid& grid, const BinnedRays& binned,
                  const std::vector<double>& intensity) {
    const size_t nc = grid.c_count(), ng = grid.gamma_count();
    double rays_flux = 0, estimate_flux = 0;
    for (size_t i = 0; i < nc; ++i)
        for (size_t j = 0; j < ng; ++j) {
            rays_flux += binned.flux[i * ng + j];
            estimate_flux += intensity[i * ng + j] * grid.solid_angle(j);
        }
    return estimate_flux > 0 ? rays_flux / estimate_flux : 1;
}

// Type C photometry on the grid (C360 repeating C0) and room for the values of every cell.
void allocate_cells(FarField& out, const FarFieldGrid& grid, bool with_sigma) {
    const size_t nc = grid.c_count(), ng = grid.gamma_count();
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
    if (with_sigma) out.sigma_deg.resize(cells);
}

// Where the photometry comes from and how it was estimated.
void add_keywords(FarField& out, const RayReader& reader, const FarFieldOptions& options) {
    Photometry& p = out.photometry;
    const RayHeader& header = reader.header();
    p.keywords["TEST"] = "far field of " + reader.path();
    if (!header.text[1].empty()) p.keywords["MANUFAC"] = header.text[1];
    if (!header.text[0].empty()) p.keywords["LUMINAIRE"] = header.text[0];
    p.keywords["_RAYS"] = std::to_string(out.rays);
    p.keywords["_SMOOTHING"] = out.method;
    p.keywords["_POLAR_AXIS"] = options.axis == PolarAxis::plus_z
                                    ? "gamma 0 is +z of the ray file; C0 is +x, C90 is +y"
                                    : "gamma 0 is -z of the ray file; C0 is +x, C90 is +y";
    if (options.quantity == FarFieldQuantity::radiometric)
        p.keywords["_RADIOMETRIC"] = "candela values are radiant intensities in W/sr";
}

}  // namespace

FarField far_field(RayReader& reader, const FarFieldOptions& options) {
    const FarFieldGrid grid(options);
    if (options.smoothing == FarFieldSmoothing::fixed && !bandwidth_allowed(options.smoothing_deg))
        throw Error("far field: smoothing bandwidth " + format_double(options.smoothing_deg) +
                    " degrees (expected " + format_double(kMinBandwidthDeg) + " to " +
                    format_double(kMaxBandwidthDeg) + ")");
    BinnedRays binned;
    bin_rays(reader, grid, options, binned);
    const size_t nc = grid.c_count(), ng = grid.gamma_count();
    std::vector<double> intensity, variance, sigma;
    std::vector<char> kind;
    if (options.smoothing == FarFieldSmoothing::none) {
        histogram_values(grid, binned, intensity, variance);
    } else {
        binned.directions.prepare();
        smoothed_values(grid, binned.directions, options, intensity, variance, sigma, kind);
    }

    FarField out;
    out.rays = binned.rays;
    out.method = smoothing_description(options, sigma, kind);
    out.flux_scale = flux_scale(grid, binned, intensity);

    allocate_cells(out, grid, !sigma.empty());
    Photometry& p = out.photometry;
    const double scale = out.flux_scale;
    const bool histogram = options.smoothing == FarFieldSmoothing::none;
    double north_flux = 0, south_flux = 0;
    for (size_t k = 0; k < nc; ++k)
        north_flux += binned.flux[k * ng], south_flux += binned.flux[k * ng + ng - 1];
    for (size_t i = 0; i <= nc; ++i) {
        const size_t source = i % nc;  // the 360 plane repeats the 0 plane
        for (size_t j = 0; j < ng; ++j) {
            const double omega = grid.solid_angle(j);
            const size_t at = p.index(i, j), from = source * ng + j;
            p.candela[at] = intensity[from] * scale;
            out.solid_angle[at] = omega;
            // The histogram's cells keep the rays' own sums (a cap's shared evenly by its cells).
            const bool cap = j == 0 || j + 1 == ng;
            out.flux[at] = !histogram ? p.candela[at] * omega
                           : cap      ? (j == 0 ? north_flux : south_flux) / double(nc)
                                      : binned.flux[from];
            out.variance[at] = variance[from] * scale * scale;
            if (!sigma.empty()) out.sigma_deg[at] = sigma[from];
            if (i < nc) out.total_flux += out.flux[at];
            if (p.candela[at] > out.max_intensity) {
                out.max_intensity = p.candela[at];
                out.max_c_deg = p.horizontal_deg[i];
                out.max_gamma_deg = p.vertical_deg[j];
            }
        }
    }

    add_keywords(out, reader, options);
    return out;
}

void round_to_uncertainty(FarField& far) {
    Photometry& p = far.photometry;
    for (size_t k = 0; k < p.candela.size(); ++k) {
        const double error = std::sqrt(far.variance[k]);
        if (!(error > 0) || !std::isfinite(error)) continue;
        // Through decimal text, so that the value is the double nearest the rounded decimal and
        // is written with those digits only.
        const int exponent = int(std::floor(std::log10(error))) - 1;
        if (exponent >= 0) {
            const double step = std::pow(10.0, exponent);
            p.candela[k] = std::round(p.candela[k] / step) * step;
        } else {
            char text[64];
            std::snprintf(text, sizeof text, "%.*f", -exponent, p.candela[k]);
            p.candela[k] = std::strtod(text, nullptr);
        }
    }
}

double written_flux(const FarField& far) {
    const Photometry& p = far.photometry;
    double sum = 0;
    for (size_t h = 0; h + 1 < p.horizontal_deg.size(); ++h)
        for (size_t v = 0; v < p.vertical_deg.size(); ++v)
            sum += p.candela[p.index(h, v)] * far.solid_angle[p.index(h, v)];
    return sum;
}

}  // namespace rayset
