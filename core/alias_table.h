// Walker's alias method (Vose's construction): an index drawn with probability proportional to
// its weight in constant time, where a search of the cumulative sums takes log n steps with a
// branch each that the processor cannot predict.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace rayset {

class AliasTable {
public:
    // A drawn index, and a uniform number in [0, 1) left over from the one that drew it (for a
    // second choice within the index's bin, as a CDF search's remainder would be).
    struct Sample {
        int index;
        double u_remapped;
    };

    AliasTable() = default;
    // Weights >= 0, some of them > 0; an index of weight 0 is never drawn.
    explicit AliasTable(const std::vector<double>& weights) {
        const std::size_t n = weights.size();
        double total = 0;
        for (double w : weights) total += w;
        bins_.resize(n);
        std::vector<uint32_t> small, large;
        std::vector<double> scaled(n);
        for (std::size_t i = 0; i < n; ++i) {
            scaled[i] = weights[i] / total * double(n);
            (scaled[i] < 1 ? small : large).push_back(uint32_t(i));
        }
        while (!small.empty() && !large.empty()) {
            const uint32_t s = small.back(), l = large.back();
            small.pop_back();
            bins_[s] = {scaled[s], l};
            scaled[l] -= 1 - scaled[s];
            if (scaled[l] < 1) {
                large.pop_back();
                small.push_back(l);
            }
        }
        // What is left holds 1 up to rounding: it keeps its whole bin.
        for (uint32_t i : large) bins_[i] = {1, i};
        for (uint32_t i : small) bins_[i] = {1, i};
    }

    bool empty() const { return bins_.empty(); }
    std::size_t size() const { return bins_.size(); }

    // u in [0, 1); the table not empty.
    Sample sample(double u) const {
        const double x = u * double(bins_.size());
        std::size_t i = std::size_t(x);
        if (i >= bins_.size()) i = bins_.size() - 1;
        const double v = x - double(i);
        const Bin& bin = bins_[i];
        if (v < bin.keep) return {int(i), v / bin.keep};
        return {int(bin.alias), (v - bin.keep) / (1 - bin.keep)};
    }

    // The probability of drawing `index`, from the table itself (for tests).
    double probability(int index) const {
        double p = 0;
        for (std::size_t i = 0; i < bins_.size(); ++i) {
            if (int(i) == index) p += bins_[i].keep;
            if (int(bins_[i].alias) == index) p += 1 - bins_[i].keep;
        }
        return p / double(bins_.size());
    }

private:
    struct Bin {
        double keep = 1;     // the share of the bin that draws its own index
        uint32_t alias = 0;  // the index the rest of it draws
    };
    std::vector<Bin> bins_;
};

}  // namespace rayset
