// The alias table against its weights: the probability each index holds in the table, the
// frequencies of a million draws, and the uniformity of the number left over for the second
// choice within a bin.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/alias_table.h"
#include "core/random.h"

namespace rayset {
namespace {

// The chi-square distribution's 99.99th percentile for `df` degrees of freedom (Wilson and
// Hilferty's cube-root approximation, within 1% from 5 degrees of freedom on).
double chi_square_9999(int df) {
    const double z = 3.719, a = 2.0 / (9.0 * df);
    return df * std::pow(1 - a + z * std::sqrt(a), 3);
}

std::vector<double> test_weights() {
    // Zeros, a heavy index and many light ones: the small and large lists both refill.
    std::vector<double> w{0, 5, 0.001, 1, 0, 3, 0.25, 7, 0.5, 0};
    Pcg32 rng(4, 1);
    for (int i = 0; i < 90; ++i) w.push_back(rng.uniform() < 0.2 ? 0.0 : rng.uniform());
    return w;
}

TEST(AliasTable, HoldsEachIndexWithItsShareOfTheWeight) {
    const std::vector<double> w = test_weights();
    double total = 0;
    for (double x : w) total += x;
    const AliasTable table(w);
    ASSERT_EQ(table.size(), w.size());
    for (size_t i = 0; i < w.size(); ++i)
        EXPECT_NEAR(table.probability(int(i)), w[i] / total, 1e-14) << "index " << i;
}

TEST(AliasTable, DrawsAsOftenAsTheWeightsSayAndLeavesAUniformRemainder) {
    const std::vector<double> w = test_weights();
    double total = 0;
    for (double x : w) total += x;
    const AliasTable table(w);
    Pcg32 rng(11, 2);
    const int draws = 1000000;
    std::vector<int> count(w.size(), 0);
    // Remainders of the heaviest index (7 of the weight), in ten bins.
    std::vector<int> remainder(10, 0);
    for (int k = 0; k < draws; ++k) {
        const AliasTable::Sample s = table.sample(rng.uniform());
        ASSERT_GE(s.u_remapped, 0.0);
        ASSERT_LT(s.u_remapped, 1.0);
        ++count[size_t(s.index)];
        if (s.index == 7) ++remainder[size_t(s.u_remapped * 10)];
    }
    // Pearson's chi-square over the indices of weight > 0, against its 99.99th percentile (a
    // true table fails it once in 10^4 seeds).
    double chi2 = 0;
    int weighted = 0;
    for (size_t i = 0; i < w.size(); ++i) {
        if (w[i] == 0) {
            EXPECT_EQ(count[i], 0) << "index " << i << " has no weight";
            continue;
        }
        const double expected = draws * w[i] / total;
        chi2 += (count[i] - expected) * (count[i] - expected) / expected;
        ++weighted;
    }
    EXPECT_LT(chi2, chi_square_9999(weighted - 1));
    // The remainder over ten bins: 9 degrees of freedom, 33.7 is the 99.99th percentile.
    double chi2_remainder = 0;
    for (int c : remainder) {
        const double expected = count[7] / 10.0;
        chi2_remainder += (c - expected) * (c - expected) / expected;
    }
    EXPECT_LT(chi2_remainder, 33.7);
}

}  // namespace
}  // namespace rayset
