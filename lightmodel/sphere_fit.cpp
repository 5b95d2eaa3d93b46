// Sphere fit of one boundary cell: farthest-point centres, then Ceres (see sphere_fit.h).
#include "lightmodel/sphere_fit.h"

#include <ceres/ceres.h>
#include <glog/logging.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace rayset::lightmodel {

namespace {

// Ceres logs a warning for every cell whose step it cannot compute (a degenerate sample set);
// the radii are exact whatever the solver did, so those warnings say nothing to a user.
void quiet_ceres() {
    static const bool once = [] {
        FLAGS_minloglevel = google::GLOG_ERROR;
        return true;
    }();
    (void)once;
}

using Point = std::array<double, 3>;

double distance2(const Point& a, const double* b) {
    const double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
    return dx * dx + dy * dy + dz * dz;
}

// Residual (c - p) / scale: linear in the centre, so Ceres' loss correction (Triggs) makes its
// steps Newton steps of the spread below, which is smooth and convex.
struct OffsetResidual {
    OffsetResidual(const Point& p, double inverse_scale) : p(p), inverse_scale(inverse_scale) {}
    template <class T>
    bool operator()(const T* centre, T* residual) const {
        for (int a = 0; a < 3; ++a) residual[a] = (centre[a] - p[a]) * inverse_scale;
        return true;
    }
    Point p;
    double inverse_scale;
};

// rho(s) = s^m on s = |c - p|^2 / scale^2: the cost sum_i rho is the L_2m norm of the samples'
// distances to the power 2m, whose minimiser tends to the smallest enclosing ball's centre as
// m grows.
class PowerLoss : public ceres::LossFunction {
public:
    explicit PowerLoss(int m) : m_(m) {}
    void Evaluate(double s, double rho[3]) const override {
        const double p2 = m_ >= 2 ? std::pow(s, m_ - 2) : 0;
        rho[0] = p2 * s * s;
        rho[1] = m_ * p2 * s;
        rho[2] = m_ * (m_ - 1) * p2;
    }

private:
    int m_;
};

double mean_nearest_neighbour(const std::vector<Point>& q) {
    double sum = 0;
    for (size_t i = 0; i < q.size(); ++i) {
        double best = std::numeric_limits<double>::infinity();
        for (size_t j = 0; j < q.size(); ++j)
            if (j != i) best = std::min(best, distance2(q[i], q[j].data()));
        sum += std::sqrt(best);
    }
    return sum / double(q.size());
}

// Farthest-point selection (see sphere_fit.h, step 2); centres as x y z r with r unset.
std::vector<std::array<double, 4>> farthest_point_centres(const std::vector<Point>& q, int count) {
    Point centroid{0, 0, 0};
    for (const Point& p : q)
        for (int a = 0; a < 3; ++a) centroid[a] += p[a] / double(q.size());
    size_t first = 0;
    for (size_t i = 1; i < q.size(); ++i)
        if (distance2(q[i], centroid.data()) < distance2(q[first], centroid.data())) first = i;

    std::vector<std::array<double, 4>> centres{{q[first][0], q[first][1], q[first][2], 0}};
    std::vector<double> nearest(q.size());
    for (size_t i = 0; i < q.size(); ++i) nearest[i] = distance2(q[i], centres[0].data());
    while (int(centres.size()) < count) {
        const size_t far =
            size_t(std::max_element(nearest.begin(), nearest.end()) - nearest.begin());
        if (nearest[far] == 0) break;  // every remaining sample repeats a centre
        centres.push_back({q[far][0], q[far][1], q[far][2], 0});
        for (size_t i = 0; i < q.size(); ++i)
            nearest[i] = std::min(nearest[i], distance2(q[i], centres.back().data()));
    }
    return centres;
}

std::vector<int> nearest_centres(const std::vector<Point>& q,
                                 const std::vector<std::array<double, 4>>& centres) {
    std::vector<int> owner(q.size());
    for (size_t i = 0; i < q.size(); ++i) {
        double best = std::numeric_limits<double>::infinity();
        for (size_t k = 0; k < centres.size(); ++k) {
            const double d = distance2(q[i], centres[k].data());
            if (d < best) best = d, owner[i] = int(k);
        }
    }
    return owner;
}

// Radius of each sphere = its farthest owned sample plus delta; -1 for a sphere owning none.
void covering_radii(const std::vector<Point>& q, const std::vector<int>& owner, double delta,
                    std::vector<std::array<double, 4>>& spheres) {
    for (auto& s : spheres) s[3] = -1;
    for (size_t i = 0; i < q.size(); ++i) {
        auto& s = spheres[owner[i]];
        s[3] = std::max(s[3], std::sqrt(distance2(q[i], s.data())) + delta);
    }
}

}  // namespace

std::vector<Sphere> fit_cell_spheres(Vec3 cell_lower, double cell_size,
                                     const std::vector<Vec3>& samples, int sphere_count,
                                     const SphereFitOptions& options) {
    if (samples.empty())
        throw std::invalid_argument("fit_cell_spheres: a boundary cell needs at least one sample");
    if (!(cell_size > 0))
        throw std::invalid_argument("fit_cell_spheres: cell size must be positive");
    std::vector<Point> q(samples.size());
    for (size_t i = 0; i < samples.size(); ++i) {
        const Vec3 r = (1 / cell_size) * (samples[i] - cell_lower);
        q[i] = {r.x, r.y, r.z};
    }
    // The spacing is capped by that of the same number of samples spread evenly over a flat
    // cell, 0.5 / sqrt(n): a few samples far apart do not make a sphere larger than the cell.
    const double cap = 0.5 / std::sqrt(double(q.size()));
    const double delta =
        options.footprint * (q.size() > 1 ? std::min(mean_nearest_neighbour(q), cap) : cap);

    auto spheres = farthest_point_centres(q, std::max(1, sphere_count));
    std::vector<int> owner = nearest_centres(q, spheres);
    covering_radii(q, owner, delta, spheres);

    // One problem for the whole cell. A sphere owning one or two samples is solved by its
    // centroid (the sample itself, their midpoint), which is exact.
    std::vector<int> owned(spheres.size(), 0);
    for (int k : owner) ++owned[k];
    ceres::Problem::Options problem_options;
    problem_options.enable_fast_removal = false;
    ceres::Problem problem(problem_options);
    for (size_t i = 0; i < q.size(); ++i) {
        auto& sphere = spheres[owner[i]];
        if (owned[owner[i]] <= 2 || !(sphere[3] > delta)) continue;
        const double scale = sphere[3] - delta;  // the first covering radius: residuals of order 1
        problem.AddResidualBlock(new ceres::AutoDiffCostFunction<OffsetResidual, 3, 3>(
                                     new OffsetResidual(q[i], 1 / scale)),
                                 new PowerLoss(options.power), sphere.data());
    }
    // Every centre moves to the centroid of its samples first: the spread's minimiser for m = 1,
    // close to the one sought, and for one or two samples the smallest enclosing ball's centre.
    std::vector<Point> centroid(spheres.size(), Point{0, 0, 0});
    for (size_t i = 0; i < q.size(); ++i)
        for (int a = 0; a < 3; ++a) centroid[owner[i]][a] += q[i][a] / owned[owner[i]];
    for (size_t k = 0; k < spheres.size(); ++k)
        if (owned[k] > 0) std::copy(centroid[k].begin(), centroid[k].end(), spheres[k].begin());

    if (problem.NumResidualBlocks() > 0) {
        ceres::Solver::Options solver;
        // The spheres do not interact, so J^T J is block diagonal: CGNR with the block-Jacobi
        // preconditioner solves it exactly in one step (measured 1.5-2x faster than dense QR).
        solver.linear_solver_type = ceres::CGNR;
        solver.preconditioner_type = ceres::JACOBI;
        solver.max_num_iterations = options.max_iterations;
        solver.num_threads = 1;
        solver.logging_type = ceres::SILENT;
        solver.minimizer_progress_to_stdout = false;
        solver.function_tolerance = options.function_tolerance;
        quiet_ceres();
        ceres::Solver::Summary summary;
        ceres::Solve(solver, &problem, &summary);
    }

    owner = nearest_centres(q, spheres);
    covering_radii(q, owner, delta, spheres);
    std::vector<Sphere> result;
    result.reserve(spheres.size());
    for (const auto& s : spheres) {
        if (s[3] < 0) continue;
        Sphere sphere{float(cell_lower.x + cell_size * s[0]),
                      float(cell_lower.y + cell_size * s[1]),
                      float(cell_lower.z + cell_size * s[2]), float(cell_size * s[3])};
        // Rounding the centre to float moves it by up to half an ulp per axis: grow the radius
        // by that so the samples stay covered in single precision too.
        const float largest =
            std::max({std::abs(sphere.x), std::abs(sphere.y), std::abs(sphere.z), sphere.r});
        sphere.r += 2 * (std::nextafter(largest, std::numeric_limits<float>::infinity()) - largest);
        result.push_back(sphere);
    }
    return result;
}

int spheres_for_count(double count, double reference_count, int max_spheres) {
    if (max_spheres < 1) throw std::invalid_argument("spheres_for_count: max_spheres must be >= 1");
    if (!(reference_count > 0)) return max_spheres;
    return int(
        std::clamp(std::round(max_spheres * count / reference_count), 1.0, double(max_spheres)));
}

double reference_count(std::vector<double> counts, double quantile) {
    if (counts.empty()) return 0;
    const size_t index = size_t(std::clamp(quantile, 0.0, 1.0) * double(counts.size() - 1) + 0.5);
    std::nth_element(counts.begin(), counts.begin() + index, counts.end());
    return counts[index];
}

}  // namespace rayset::lightmodel
