// The canonical random numbers of one camera sample: the first dimensions of its path from an
// Owen-scrambled Sobol sequence, the rest from PCG32.
//
// Pixel x's sample k (pass p with one sample a pass: k = p) takes, for its d-th pair of
// dimensions, the point of Sobol's first two dimensions (a (0,2)-sequence) at a shuffled
// index, each coordinate Owen-scrambled; the shuffle and the scrambles are hashes of (seed,
// pixel, d) (Burley 2020, "Practical Hash-based Owen Scrambling": padding by independent
// shuffles). So:
// - every value is uniform on [0, 1) and pairs are independent of each other: estimates stay
//   unbiased, as with independent random numbers;
// - a pixel's first 2^m samples, in every pair, are a (0,m,2)-net: one point in each of the
//   elementary intervals of area 2^-m (the shuffle maps the first 2^m indices onto an aligned
//   block of 2^m, and any such block of a (0,2)-sequence is a net). Light and BSDF samples,
//   pixel positions and the like are stratified over the passes, which makes the error of
//   smooth integrands fall faster than passes^-0.5;
// - a sample's values depend on (seed, pixel, k) alone: processes and resumed renders that
//   render the same passes draw the same numbers.
// Past kSequencePairs pairs (the path's later vertices: on tests/bench/grey_box.sh's room, 64
// pairs give the error of 6) and for a sampler made from a bare PCG32, the values come from the
// PCG32 stream, in the order asked: get_1d() one uniform_float(), get_2d() two.
// The film's standard errors, taken from the spread of the passes as if they were independent,
// overstate the error of what the sequence stratifies.
#pragma once

#include <cstdint>

#include "core/random.h"

namespace rayset::tracer {

class Sampler {
public:
    // Pairs of dimensions a sample takes from the sequence: the pixel's position and the first
    // vertex's light and BSDF samples.
    static constexpr uint32_t kSequencePairs = 6;

    // Every value from `rng`.
    explicit Sampler(Pcg32& rng) : rng_(rng) {}
    // Sample `index` of point `point` (a pixel or receiver cell) of the render seeded `seed`;
    // past the sequence, from `rng`.
    Sampler(Pcg32& rng, uint64_t seed, uint64_t point, uint32_t index)
        : rng_(rng),
          point_hash_(
              splitmix64_finalise(seed ^ splitmix64_finalise(point + 0x9E3779B97F4A7C15ULL))),
          reversed_index_(reverse_bits(index)),
          pairs_left_(kSequencePairs) {}

    // One value in [0, 1).
    double get_1d() {
        if (pairs_left_ == 0) return rng_.uniform_float();
        const uint64_t h = next_pair_hash();
        // Sobol's first dimension is the bit reversal of the index, which undoes the one
        // Owen scrambling's formula starts with.
        return to_unit(reverse_bits(laine_karras(shuffled(h), uint32_t(h >> 32))));
    }

    // Two values in [0, 1), stratified together.
    void get_2d(double& u1, double& u2) {
        if (pairs_left_ == 0) {
            u1 = rng_.uniform_float();
            u2 = rng_.uniform_float();
            return;
        }
        const uint64_t h = next_pair_hash();
        const uint32_t i = shuffled(h);
        u1 = to_unit(reverse_bits(laine_karras(i, uint32_t(h >> 32))));
        u2 = to_unit(reverse_bits(
            laine_karras(second_dimension_reversed(i), uint32_t(splitmix64_finalise(h)))));
    }

    // The stream past the sequence, for what the sequence does not cover.
    Pcg32& rng() { return rng_; }

    // Sobol's second dimension at `index`, bit-reversed: its generator matrix is Pascal's
    // triangle mod 2, so bit k of the reversed value is the XOR of the index bits j whose set
    // bits include k's (Lucas' theorem), a superset sum over bit positions.
    static uint32_t second_dimension_reversed(uint32_t index) {
        uint32_t x = index;
        x ^= (x >> 1) & 0x55555555u;
        x ^= (x >> 2) & 0x33333333u;
        x ^= (x >> 4) & 0x0F0F0F0Fu;
        x ^= (x >> 8) & 0x00FF00FFu;
        x ^= (x >> 16) & 0x0000FFFFu;
        return x;
    }
    static uint32_t reverse_bits(uint32_t x) {
        x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
        x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
        x = ((x >> 4) & 0x0F0F0F0Fu) | ((x & 0x0F0F0F0Fu) << 4);
        return __builtin_bswap32(x);
    }
    // A random permutation of 32-bit words in which bit j of the result depends on bits 0..j
    // of x alone (additions and multiplications carry upward only), so that between two bit
    // reversals it is an Owen scrambling: each digit flipped by a hash of the digits above it.
    // Vegdahl's constants (2021, "Building a better LK hash"), better mixed than Laine and
    // Karras' original ones.
    static uint32_t laine_karras(uint32_t x, uint32_t seed) {
        x ^= x * 0x3D20ADEAu;
        x += seed;
        x *= (seed >> 16) | 1u;
        x ^= x * 0x05526C56u;
        x ^= x * 0x53A22864u;
        return x;
    }

private:
    static double to_unit(uint32_t x) { return x * 0x1p-32; }
    uint64_t next_pair_hash() {
        --pairs_left_;
        return splitmix64_finalise(point_hash_ +
                                   uint64_t(kSequencePairs - pairs_left_) * 0x9E3779B97F4A7C15ULL);
    }
    // The pair's shuffled index: the sample index Owen-scrambled with its least significant
    // bit as the top digit.
    uint32_t shuffled(uint64_t pair_hash) const {
        return reverse_bits(laine_karras(reversed_index_, uint32_t(pair_hash)));
    }

    Pcg32& rng_;
    uint64_t point_hash_ = 0;
    uint32_t reversed_index_ = 0;
    uint32_t pairs_left_ = 0;
};

}  // namespace rayset::tracer
