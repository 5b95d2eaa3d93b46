// The camera sampler (tracer/render/sampler.h): its pairs are (0,m,2)-nets over a point's first
// 2^m samples and over the next 2^m, its values uniform, its pairs and points independent, and
// it falls back to the PCG32 stream in the stream's own order.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "tracer/render/sampler.h"

using namespace rayset;
using namespace rayset::tracer;

namespace {

struct Point2 {
    double u1, u2;
};

// Pair `pair` (counted from 0; pairs before it drawn with get_2d) of samples [first, first + n)
// of point `point`.
std::vector<Point2> pair_of_samples(uint64_t seed, uint64_t point, uint32_t pair, uint32_t first,
                                    uint32_t n) {
    std::vector<Point2> out;
    Pcg32 rng(1, 2);
    for (uint32_t k = first; k < first + n; ++k) {
        Sampler sampler(rng, seed, point, k);
        Point2 p{};
        for (uint32_t d = 0; d <= pair; ++d) sampler.get_2d(p.u1, p.u2);
        out.push_back(p);
    }
    return out;
}

// Whether every elementary interval [i 2^-a, (i+1) 2^-a) x [j 2^-(m-a), (j+1) 2^-(m-a)) holds
// exactly one of the 2^m points, for every a in 0..m.
bool is_net(const std::vector<Point2>& points, int m) {
    for (int a = 0; a <= m; ++a) {
        std::vector<int> count(size_t(1) << m, 0);
        for (const Point2& p : points) {
            const size_t i = size_t(std::ldexp(p.u1, a)), j = size_t(std::ldexp(p.u2, m - a));
            ++count[(i << (m - a)) | j];
        }
        for (int c : count)
            if (c != 1) return false;
    }
    return true;
}

TEST(Sampler, SecondSobolDimensionMatchesItsDirectionNumbers) {
    // Sobol's second dimension by its definition: direction numbers v_1 = 1/2 and
    // v_(k+1) = v_k xor v_k / 2 (all m_k = 1), XORed for the index's set bits.
    for (uint32_t index = 0; index < 5000; ++index) {
        uint32_t v = 1u << 31, x = 0;
        for (uint32_t i = index; i; i >>= 1, v ^= v >> 1)
            if (i & 1) x ^= v;
        ASSERT_EQ(Sampler::reverse_bits(Sampler::second_dimension_reversed(index)), x) << index;
    }
}

TEST(Sampler, EveryPairIsANetOverPowerOfTwoRunsOfSamples) {
    for (uint64_t point : {0ull, 1ull, 77777ull})
        for (uint32_t pair : {0u, 1u, 5u, Sampler::kSequencePairs - 1})
            for (int m : {2, 5, 8, 10}) {
                const uint32_t n = 1u << m;
                EXPECT_TRUE(is_net(pair_of_samples(7, point, pair, 0, n), m))
                    << "point " << point << " pair " << pair << " first 2^" << m;
                EXPECT_TRUE(is_net(pair_of_samples(7, point, pair, n, n), m))
                    << "point " << point << " pair " << pair << " second 2^" << m;
            }
}

TEST(Sampler, OneDimensionalValuesAreStratified) {
    const int m = 9;
    std::vector<int> count(size_t(1) << m, 0);
    Pcg32 rng;
    for (uint32_t k = 0; k < (1u << m); ++k) {
        Sampler sampler(rng, 3, 12, k);
        double u1, u2;
        sampler.get_2d(u1, u2);
        ++count[size_t(std::ldexp(sampler.get_1d(), m))];
    }
    for (int c : count) EXPECT_EQ(c, 1);
}

// Pearson's correlation of two samples.
double correlation(const std::vector<double>& a, const std::vector<double>& b) {
    const double n = double(a.size());
    double sa = 0, sb = 0, saa = 0, sbb = 0, sab = 0;
    for (size_t i = 0; i < a.size(); ++i) {
        sa += a[i], sb += b[i], saa += a[i] * a[i], sbb += b[i] * b[i], sab += a[i] * b[i];
    }
    const double cov = sab / n - sa / n * (sb / n);
    return cov / std::sqrt((saa / n - sa / n * (sa / n)) * (sbb / n - sb / n * (sb / n)));
}

TEST(Sampler, PairsAndPointsAreUncorrelatedAndValuesUniform) {
    // 4096 samples of independent uniforms have a correlation of standard deviation 1/64; the
    // bound 5/64 is passed by chance with probability 6e-7 per figure. Seeds fixed.
    const uint32_t n = 4096;
    const double bound = 5.0 / 64;
    const auto a = pair_of_samples(11, 5, 0, 0, n), b = pair_of_samples(11, 5, 1, 0, n),
               c = pair_of_samples(11, 6, 0, 0, n);
    auto column = [](const std::vector<Point2>& p, bool second) {
        std::vector<double> v;
        for (const Point2& q : p) v.push_back(second ? q.u2 : q.u1);
        return v;
    };
    EXPECT_LT(std::abs(correlation(column(a, false), column(b, false))), bound);
    EXPECT_LT(std::abs(correlation(column(a, true), column(b, true))), bound);
    EXPECT_LT(std::abs(correlation(column(a, false), column(b, true))), bound);
    EXPECT_LT(std::abs(correlation(column(a, false), column(c, false))), bound);
    EXPECT_LT(std::abs(correlation(column(a, true), column(c, true))), bound);

    // The value of pair 3 at sample 0 across 20 000 points: uniform (chi-square, 20 bins,
    // 19 degrees of freedom; 50.0 is exceeded with probability 1.3e-4).
    std::vector<int> bins(20, 0);
    Pcg32 rng;
    for (uint64_t point = 0; point < 20000; ++point) {
        Sampler sampler(rng, 9, point, 0);
        double u1 = 0, u2 = 0;
        for (int d = 0; d < 4; ++d) sampler.get_2d(u1, u2);
        ASSERT_GE(u1, 0);
        ASSERT_LT(u1, 1);
        ++bins[size_t(u1 * 20)];
    }
    double chi2 = 0;
    for (int b : bins) chi2 += std::pow(b - 1000.0, 2) / 1000.0;
    EXPECT_LT(chi2, 50.0);
}

TEST(Sampler, FallsBackToTheStreamInItsOrder) {
    Pcg32 a(5, 9), b(5, 9);
    Sampler bare(a);
    double u1, u2;
    bare.get_2d(u1, u2);
    EXPECT_EQ(u1, b.uniform_float());
    EXPECT_EQ(u2, b.uniform_float());
    EXPECT_EQ(bare.get_1d(), b.uniform_float());

    // Past the sequence's pairs, the stream; before, the stream is left alone.
    Pcg32 c(5, 9), d(5, 9);
    Sampler sequence(c, 1, 2, 3);
    for (uint32_t k = 0; k < Sampler::kSequencePairs; ++k) sequence.get_2d(u1, u2);
    EXPECT_EQ(sequence.get_1d(), d.uniform_float());
    // The same sample again: the same values.
    Pcg32 e;
    Sampler again(e, 1, 2, 3), other(e, 1, 2, 4);
    double v1, v2, w1, w2;
    Pcg32 f;
    Sampler first(f, 1, 2, 3);
    first.get_2d(v1, v2);
    again.get_2d(w1, w2);
    EXPECT_EQ(v1, w1);
    EXPECT_EQ(v2, w2);
    other.get_2d(w1, w2);
    EXPECT_NE(v1, w1);
}

}  // namespace
