// Far-field intensity from a limited set of rays: kernel density estimation and local fits on
// the sphere.
//
// A histogram of 10^5 rays on a 5 x 2.5 degree grid holds a handful of rays per cell: its
// values scatter by 20-30% from cell to cell and its maximum is a cell that caught a few rays
// too many. The estimate here replaces each ray by a kernel on the sphere, the difference of two
// von Mises-Fisher densities K = 2 vMF(kappa) - vMF(kappa / 2) (Stephanou's "twicing"): it
// integrates to one, so the flux stays the rays', and it reproduces spherical harmonics of
// degree 0 and 1 exactly (2 coth k - coth(k/2) = tanh(k/2)), so a Lambertian far field is not
// flattened the way a single vMF kernel flattens it (by sigma^2 relative).
//
// Local fits: where the intensity curves strongly (the flanks of a narrow lobe) any kernel of
// useful width is biased. There the logarithm of the intensity is what is smooth (a cos^n lobe is
// nearly exp(-n theta^2 / 2)), and a local log-quadratic fit with Gaussian weights has a closed
// form: in the tangent plane at u, the intensity exp(a + g.t - t.H.t / 2) times the weight
// exp(-|t|^2 / (2 sigma^2)) is a Gaussian, whose mean m and covariance V are the weighted moments
// of the rays, so I(u) = exp(a) = S0 / (2 pi sqrt(det V)) exp(-m.V^-1.m / 2) with S0 the
// weighted flux (Loader's local likelihood, Ann. Statist. 24, 1996, by moments). It reproduces
// Gaussian lobes exactly and a flat intensity as the Gaussian kernel does; its noise is that of
// the equivalent kernel G (2 - r^2 / (2 sigma^2)), 1.36 times the twiced kernel's variance.
//
// Edge fits: at the horizon of a flat emitter the intensity falls linearly to zero and stays
// there, a kink that biases every kernel and every smooth fit reaching across it, so that the
// flanks of a flat LED were estimated with narrow kernels and much noise. A flat Lambertian
// emitter's intensity is max(0, c.v), linear in the direction v and cut at zero; in the gnomonic
// projection about u (p = v / (u.v) - u) the rays weighted by a Gaussian w(p) / (u.v)^4 see the
// plane function (a + b.p)_+ exactly, whose weighted flux and first moment give a = I(u) in
// closed form up to one monotone equation in the edge's distance (solved by bisection). It is
// offered only where the rays' second moments are those of such an edge (within their noise):
// elsewhere it is a Gaussian kernel, biased by curvature.
//
// Choice: sigma = 1/sqrt(kappa) and the kind of estimate are chosen per direction among the
// three kinds on a ladder of bandwidths growing by sqrt(2) from DirectionResolution::min_sigma_deg
// to max_sigma_deg by Goldenshluger and Lepski's rule (Ann. Statist. 39, 2011): the bias of an
// estimate is bounded by how far it lies from those of the same or smaller bandwidths beyond the
// noise of their difference (estimates from the same rays are correlated, as their kernels
// overlap: the noise of a difference is far below either's), and the estimate with the least
// bound plus noise wins. A log-quadratic fit is held only to the kernels of at most half its
// width: a kernel as wide as a fit that follows a lobe flattens it (the twiced kernel's bias
// grows as sigma^4, so at half the width it is a sixteenth). Where the intensity is flat the
// kernel grows and the noise falls; where it curves the estimates of larger kernels move away and
// it stops, or a local fit that agrees with the smaller ones wins.
//
// Standard error: the rays as a Poisson sample, sqrt(sum of (flux K)^2) with K the kernel or the
// fit's equivalent kernel, with one ray of the mean flux at the kernel's peak added, so that a
// direction without rays does not claim to be known exactly. It states the noise; the smoothing
// bias comes on top, held near the noise by the rule (2-standard-error intervals hold the truth
// for 89 to 95% of the values of the analytic sources at 10^5 and 10^6 rays, against 95% for
// unbiased values; for a cos^20 lobe at 10^7 rays, whose flanks local fits follow with a bias
// below their noise at fewer rays, 82%).
//
// Cost: the rays are binned once into the finest cells (0.25 degrees for a far field) that keep
// their flux, squared flux and flux-weighted mean direction, merged 2 x 2 into coarser levels by
// prepare(); a kernel of width sigma sums the bins of the coarsest level whose bins are at most
// sigma / 8 wide (far fields; DirectionResolution::bins_per_sigma).
#pragma once

#include <array>
#include <cstddef>
#include <vector>

namespace rayset {

// The finest bins of a direction histogram and its bandwidth ladder.
struct DirectionResolution {
    double finest_step_deg;
    int levels;  // bins of finest_step_deg x 2^l, l < levels, each dividing 180
    double min_sigma_deg, max_sigma_deg;
    // A kernel of width sigma sums the coarsest bins at most sigma / bins_per_sigma wide: their
    // spread (step / sqrt(12)) widens it by 1 / (12 bins_per_sigma^2) of its variance.
    double bins_per_sigma;
    bool local_fits;  // the bandwidth rule chooses among local fits too
};
// Far fields: 0.25 to 4 degree bins, bandwidths from 1 to 16 degrees, kernels and local fits.
inline constexpr DirectionResolution kFarFieldResolution{0.25, 5, 1, 16, 8, true};

class DirectionHistogram {
public:
    // Throws std::invalid_argument when a level's bins do not divide 180 degrees.
    explicit DirectionHistogram(const DirectionResolution& resolution = kFarFieldResolution);

    // A ray's flux toward the unit direction (x, y, polar): polar is the component along the
    // far field's polar axis, C = atan2(y, x).
    void add(double x, double y, double polar, double flux);

    // Adds the rays of `other`, whose finest bins must be the same (std::invalid_argument
    // otherwise), before either is prepared.
    void merge(const DirectionHistogram& other);

    // Ends the adding: every estimate needs it first.
    void prepare();

    double total_flux() const { return total_flux_; }
    double total_square() const { return total_square_; }
    double ray_count() const { return rays_; }

    enum class Kind {
        kernel,         // at(): the twiced kernel
        log_quadratic,  // local_fit()
        edge,           // edge_fit()
    };
    struct Estimate {
        double intensity = 0;       // flux per steradian
        double standard_error = 0;  // of the intensity
        double sigma_deg = 0;       // the bandwidth it was made with
        Kind kind = Kind::kernel;
        bool local() const { return kind != Kind::kernel; }
    };
    // Kernel estimate toward the unit direction (x, y, polar) with bandwidth sigma_deg.
    Estimate at(double x, double y, double polar, double sigma_deg) const;
    // Local log-quadratic fit toward (x, y, polar) with Gaussian weights of bandwidth sigma_deg.
    Estimate local_fit(double x, double y, double polar, double sigma_deg) const;
    // Local fit of max(0, c.v), a linear function of the direction v cut at zero, toward
    // (x, y, polar) with Gaussian weights of bandwidth sigma_deg in the gnomonic projection.
    Estimate edge_fit(double x, double y, double polar, double sigma_deg) const;
    // The estimate of the kind (kernel or local fit) and bandwidth of `chosen` at (x, y, polar).
    Estimate at_kernel_of(double x, double y, double polar, const Estimate& chosen) const;
    // The same with the bandwidth chosen from the rays (see the top of this file).
    Estimate adaptive(double x, double y, double polar) const;

private:
    struct Bin {
        double flux = 0, square = 0;
        std::array<double, 3> direction{};  // flux-weighted sum of directions
    };
    struct Level {
        double step_deg = 0;
        size_t rows = 0, columns = 0;  // gamma rows from the polar axis, C columns from C 0
        std::vector<Bin> bins;         // row-major
        // Unit mean directions of the bins (zero for an empty bin), made by prepare().
        std::vector<std::array<double, 3>> mean;
    };
    const Level& level_for(double sigma_deg) const;
    // edge_fit(), and whether the rays' spread along the gradient is that of an edge.
    Estimate edge_fit(double x, double y, double polar, double sigma_deg, bool& edge_like) const;
    // Calls visit(bin, mean direction, cosine to u) for each bin with flux within `radius` of u.
    template <class Visit>
    void visit_bins(const Level& level, double x, double y, double polar, double radius,
                    Visit&& visit) const;

    DirectionResolution resolution_;
    std::vector<Level> levels_;  // levels_[0] is filled by add(), the others by prepare()
    double total_flux_ = 0, total_square_ = 0, rays_ = 0;
};

}  // namespace rayset
