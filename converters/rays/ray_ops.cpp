#include "converters/rays/ray_ops.h"

#include "converters/rays/ray_ops_detail.h"
#include "core/geometry.h"
#include "core/random.h"

#include <fmt/format.h>
#include <algorithm>
#include <cmath>
#include <limits>

namespace rayset {

namespace {

// Knuth's Algorithm S: ray i is kept with probability (k - kept) / (n - i), which keeps
// exactly k rays and makes every k-subset equally likely. One draw per ray until k are kept,
// so a second selector with the same seed replays the same choice. When n - i = k - kept the
// probability is 1, so the last rays are taken without fail.
class Selection {
public:
    Selection(uint64_t n, uint64_t k, uint64_t seed) : rng_(seed), n_(n), k_(k) {}
    bool next() {
        if (kept_ == k_) return ++seen_, false;
        const bool take = rng_.uniform() < double(k_ - kept_) / double(n_ - seen_);
        ++seen_;
        kept_ += take;
        return take;
    }
    uint64_t seen() const { return seen_; }

private:
    Pcg32 rng_;
    uint64_t n_, k_, seen_ = 0, kept_ = 0;
};

double matrix_distance_from_identity(const Matrix3& m) {
    double worst = 0;
    for (int i = 0; i < 9; ++i) worst = std::max(worst, std::abs(m[i] - kIdentity3[i]));
    return worst;
}

double determinant(const Matrix3& m) {
    return m[0] * (m[4] * m[8] - m[5] * m[7]) - m[1] * (m[3] * m[8] - m[5] * m[6]) +
           m[2] * (m[3] * m[7] - m[4] * m[6]);
}

std::array<double, 3> apply(const Matrix3& m, double x, double y, double z) {
    return {m[0] * x + m[1] * y + m[2] * z, m[3] * x + m[4] * y + m[5] * z,
            m[6] * x + m[7] * y + m[8] * z};
}

}  // namespace

// ---- subsample ---------------------------------------------------------------------------------

namespace {

// The number of rays to keep: the count asked for, or the fraction of n rounded.
uint64_t rays_to_keep(const std::string& input, const SubsampleOptions& options, uint64_t n) {
    uint64_t k = options.count;
    if (k == 0) {
        if (!(options.fraction > 0 && options.fraction <= 1))
            fail(input, fmt::format("subsample: the fraction to keep is {}, not a number in (0, 1]",
                                    options.fraction));
        k = static_cast<uint64_t>(std::llround(options.fraction * double(n)));
        if (k == 0)
            fail(input, fmt::format("subsample: keeping {} of {} rays keeps none; ask for a count "
                                    "or a larger fraction",
                                    options.fraction, n));
    }
    if (k > n)
        fail(input, fmt::format("subsample: {} rays asked for, but the file holds only {}", k, n));
    return k;
}

struct FluxSums {
    double radiant = 0, luminous = 0;
};

// The first pass: the fluxes of the rays the selection keeps.
FluxSums kept_flux(RayReader& reader, const std::string& input, uint64_t k, uint64_t seed,
                   const Progress& progress) {
    const RayHeader& in = reader.header();
    const uint64_t n = in.ray_count;
    FluxSums kept;
    Selection select(n, k, seed);
    RayChunk chunk;
    while (reader.read(chunk)) {
        for (const Ray& r : chunk.rays)
            if (select.next()) {
                if (in.has_radiant) kept.radiant += r.radiant;
                if (in.has_luminous) kept.luminous += r.luminous;
            }
        if (progress) progress(0.5 * reader.progress());
    }
    if (select.seen() != n)
        fail(input, fmt::format("subsample: the header counts {} rays but the file holds {}", n,
                                select.seen()));
    return kept;
}

// The second pass: the same selection again, writing the kept rays scaled.
void write_kept(RayReader& reader, RayEncoder& out, uint64_t seed, double radiant_scale,
                double luminous_scale, RayOpReport& report, const Progress& progress) {
    const RayHeader& in = reader.header();
    Selection select(in.ray_count, report.header.ray_count, seed);
    RayChunk chunk, kept;
    while (reader.read(chunk)) {
        kept.clear();
        kept.first_index = report.totals.rays;
        for (size_t i = 0; i < chunk.rays.size(); ++i)
            if (select.next()) detail::copy_ray(chunk, i, kept);
        for (Ray& r : kept.rays) {
            if (in.has_radiant) r.radiant = float(r.radiant * radiant_scale);
            if (in.has_luminous) r.luminous = float(r.luminous * luminous_scale);
        }
        if (!kept.rays.empty()) out.write(kept);
        detail::add_totals(report.totals, report.header, kept);
        if (progress) progress(0.5 + 0.5 * reader.progress());
    }
    out.finish();
    report.dropped = out.dropped();
}

}  // namespace

RayOpReport subsample_rays(const std::string& input, const std::string& output, RayFormat format,
                           const SubsampleOptions& options, const RayReadOptions& read,
                           const Progress& progress) {
    auto first = open_rays(input, read);
    const RayHeader& in = first->header();
    const uint64_t k = rays_to_keep(input, options, in.ray_count);
    const FluxSums kept = kept_flux(*first, input, k, options.seed, progress);
    const RayTotals total = first->totals();
    // The factor that brings the kept rays' flux back to the file's total.
    auto scale_for = [&](bool present, double sum_in, double sum_kept, const char* what) {
        if (!present || sum_in == 0) return 1.0;
        if (sum_kept <= 0)
            fail(input, fmt::format("subsample: the {} rays kept with seed {} carry no {} flux, so "
                                    "the total cannot be kept; keep more rays or use another seed",
                                    k, options.seed, what));
        return sum_in / sum_kept;
    };
    const double radiant_scale = scale_for(in.has_radiant, total.radiant, kept.radiant, "radiant");
    const double luminous_scale =
        scale_for(in.has_luminous, total.luminous, kept.luminous, "luminous");

    RayOpReport report;
    report.warnings = first->warnings();
    report.header = in;
    report.header.ray_count = k;
    report.header.stated_radiant = in.has_radiant ? total.radiant : std::nan("");
    report.header.stated_luminous = in.has_luminous ? total.luminous : std::nan("");

    auto second = open_rays(input, read);
    auto out = create_rays(output, format, report.header);
    write_kept(*second, *out, options.seed, radiant_scale, luminous_scale, report, progress);
    return report;
}

// ---- transform ---------------------------------------------------------------------------------

Matrix3 rotation_about_axis(const std::array<double, 3>& axis, double degrees) {
    const double length = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
    if (!(length > 0) || !std::isfinite(length))
        throw Error(
            fmt::format("rotation axis ({}, {}, {}) has no direction", axis[0], axis[1], axis[2]));
    if (!std::isfinite(degrees))
        throw Error(fmt::format("rotation angle {} is not a number", degrees));
    const double x = axis[0] / length, y = axis[1] / length, z = axis[2] / length;
    const double a = degrees * kPi / 180, c = std::cos(a), s = std::sin(a), t = 1 - c;
    // Rodrigues' formula.
    return {t * x * x + c,     t * x * y - s * z, t * x * z + s * y,
            t * x * y + s * z, t * y * y + c,     t * y * z - s * x,
            t * x * z - s * y, t * y * z + s * x, t * z * z + c};
}

Matrix3 multiply(const Matrix3& a, const Matrix3& b) {
    Matrix3 m{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k) m[3 * i + j] += a[3 * i + k] * b[3 * k + j];
    return m;
}

Matrix3 transpose(const Matrix3& m) {
    return {m[0], m[3], m[6], m[1], m[4], m[7], m[2], m[5], m[8]};
}

RayTransformer::RayTransformer(const RayTransform& t, const RayHeader& header,
                               const std::string& file)
    : header_(header), rotation_(t.rotation) {
    if (!(t.scale > 0) || !std::isfinite(t.scale))
        fail(file,
             fmt::format("transform: the scale factor is {}, not a positive number", t.scale));
    for (double v : t.rotation)
        if (!std::isfinite(v))
            fail(file, "transform: the rotation matrix holds a value that is not a number");
    const double off = matrix_distance_from_identity(multiply(t.rotation, transpose(t.rotation)));
    if (off > 1e-6 || determinant(t.rotation) < 0)
        fail(file,
             fmt::format("transform: the 3x3 matrix is not a rotation (R x R^T differs from the "
                         "identity by {:.3g}, "
                         "determinant {:.6g}); give an orthonormal matrix with determinant +1",
                         off, determinant(t.rotation)));
    for (double v : t.translation)
        if (!std::isfinite(v))
            fail(file, "transform: the translation holds a value that is not a number");

    const LengthUnit unit = t.unit.value_or(header.unit);
    const double unit_factor = millimetres_per(header.unit) / millimetres_per(unit);
    const double translation_factor =
        millimetres_per(t.translation_unit.value_or(unit)) / millimetres_per(unit);
    rotates_ = t.rotation != kIdentity3;
    linear_ = t.rotation;
    for (double& v : linear_) v *= t.scale * unit_factor;
    for (int i = 0; i < 3; ++i) translation_[i] = t.translation[i] * translation_factor;

    header_.unit = unit;
    const Vec3f& o = header.data_origin;
    auto p = ::rayset::apply(linear_, o.x, o.y, o.z);
    header_.data_origin = {float(p[0] + translation_[0]), float(p[1] + translation_[1]),
                           float(p[2] + translation_[2])};
    Vec3f& where = header_.placement.location;
    where = {float(where.x * unit_factor), float(where.y * unit_factor),
             float(where.z * unit_factor)};

    extras_ = header.extras.size();
    const ExtraKind axis[3] = {ExtraKind::ellipse_x, ExtraKind::ellipse_y, ExtraKind::ellipse_z};
    for (size_t e = 0; e < extras_; ++e)
        for (int a = 0; a < 3; ++a)
            if (header.extras[e].kind == axis[a]) ellipse_[a] = static_cast<int>(e);
    if (std::count(ellipse_.begin(), ellipse_.end(), -1) != 0) ellipse_ = {-1, -1, -1};
}

void RayTransformer::apply(RayChunk& chunk) const {
    for (size_t i = 0; i < chunk.rays.size(); ++i) {
        Ray& r = chunk.rays[i];
        auto o = ::rayset::apply(linear_, r.origin.x, r.origin.y, r.origin.z);
        r.origin = {float(o[0] + translation_[0]), float(o[1] + translation_[1]),
                    float(o[2] + translation_[2])};
        if (!rotates_) continue;
        auto d = ::rayset::apply(rotation_, r.direction.x, r.direction.y, r.direction.z);
        const double length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        r.direction = {float(d[0] / length), float(d[1] / length), float(d[2] / length)};
        if (ellipse_[0] >= 0) {
            float* e = chunk.extra.data() + i * extras_;
            auto a = ::rayset::apply(rotation_, e[ellipse_[0]], e[ellipse_[1]], e[ellipse_[2]]);
            for (int k = 0; k < 3; ++k) e[ellipse_[k]] = float(a[k]);
        }
    }
}

RayOpReport transform_rays(const std::string& input, const std::string& output, RayFormat format,
                           const RayTransform& transform, const RayReadOptions& read,
                           const Progress& progress) {
    auto reader = open_rays(input, read);
    RayTransformer transformer(transform, reader->header(), input);
    RayOpReport report;
    report.header = transformer.header();
    auto out = create_rays(output, format, report.header);
    RayChunk chunk;
    while (reader->read(chunk)) {
        transformer.apply(chunk);
        out->write(chunk);
        detail::add_totals(report.totals, report.header, chunk);
        if (progress) progress(reader->progress());
    }
    out->finish();
    report.warnings = reader->warnings();
    report.dropped = out->dropped();
    return report;
}

}  // namespace rayset
