// A small seedable random number generator whose output is the same on every platform and
// with every standard library: PCG32 (O'Neill 2014, "PCG: A Family of Simple Fast
// Space-Efficient Statistically Good Algorithms for Random Number Generation", the
// XSH-RR output on a 64-bit LCG). The std:: engines are portable but the std:: distributions
// are not, so the uniform variates are built here from the raw bits.
#pragma once

#include <cstdint>

namespace rayset {

// SplitMix64's finaliser (Steele et al. 2014): a bijection of 64-bit words whose outputs for
// neighbouring inputs look unrelated, used to derive seeds and hashes from small integers.
inline uint64_t splitmix64_finalise(uint64_t z) {
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
}

class Pcg32 {
public:
    // `stream` selects one of 2^63 independent sequences for the same seed.
    explicit Pcg32(uint64_t seed = 0, uint64_t stream = 0) : increment_((stream << 1) | 1u) {
        next_u32();
        state_ += seed;
        next_u32();
    }

    uint32_t next_u32() {
        const uint64_t old = state_;
        state_ = old * kMultiplier + increment_;
        const uint32_t xorshifted = static_cast<uint32_t>(((old >> 18) ^ old) >> 27);
        const uint32_t rotation = static_cast<uint32_t>(old >> 59);
        return (xorshifted >> rotation) | (xorshifted << ((32 - rotation) & 31));
    }

    // Uniform in [0, 1) with 53 random bits (two draws); every value is exactly k / 2^53.
    double uniform() {
        const uint64_t high = next_u32() >> 5;  // 27 bits
        const uint64_t low = next_u32() >> 6;   // 26 bits
        return double((high << 26) | low) * (1.0 / 9007199254740992.0);
    }

    // Uniform in [0, 1) with 24 random bits (one draw); every value is exactly k / 2^24.
    float uniform_float() { return float(next_u32() >> 8) * (1.0f / 16777216.0f); }

    // Uniform integer in [0, bound) without modulo bias (Lemire's rejection on the low word).
    uint32_t below(uint32_t bound) {
        uint64_t product = uint64_t(next_u32()) * bound;
        uint32_t low = static_cast<uint32_t>(product);
        if (low < bound) {
            const uint32_t threshold = static_cast<uint32_t>(-bound) % bound;
            while (low < threshold) {
                product = uint64_t(next_u32()) * bound;
                low = static_cast<uint32_t>(product);
            }
        }
        return static_cast<uint32_t>(product >> 32);
    }

private:
    static constexpr uint64_t kMultiplier = 6364136223846793005ULL;
    uint64_t state_ = 0;
    uint64_t increment_;
};

}  // namespace rayset
