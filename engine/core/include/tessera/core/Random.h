#pragma once
/// @file Random.h
/// A small deterministic PRNG (PCG32, O'Neill 2014).
///
/// The one random generator of the code base: every seeded feature (camera
/// paths, terrain generation, meteor showers, crowds, procedural displacement,
/// the creature generator) and every test that wants random input uses this
/// instead of <random>'s distributions, whose output is
/// implementation-defined: the same seed must give the same bytes with any
/// standard library. (Noise lattices hash their coordinates instead, since
/// they are read in any order; that is a hash, not a generator.)

#include <cstdint>

namespace tessera {

class Random {
public:
    /// Seeds the generator; `stream` selects one of 2^63 independent sequences.
    explicit Random(uint64_t seed, uint64_t stream = 0x14057b7ef767814fULL) {
        mInc = (stream << 1u) | 1u;
        nextU32();
        mState += seed;
        nextU32();
    }

    /// Next uniformly distributed 32-bit value.
    uint32_t nextU32() {
        uint64_t old = mState;
        mState = old * 6364136223846793005ULL + mInc;
        uint32_t xorShifted = static_cast<uint32_t>(((old >> 18u) ^ old) >> 27u);
        uint32_t rot = static_cast<uint32_t>(old >> 59u);
        return (xorShifted >> rot) | (xorShifted << ((~rot + 1u) & 31u));
    }

    /// Uniform float in [0, 1), exactly representable (24 random bits).
    float nextFloat() { return static_cast<float>(nextU32() >> 8) * (1.0f / 16777216.0f); }

    /// Uniform float in [lo, hi).
    float range(float lo, float hi) { return lo + (hi - lo) * nextFloat(); }

    /// Next uniformly distributed 64-bit value (two 32-bit draws, high first).
    uint64_t nextU64() {
        const uint64_t high = nextU32();
        return (high << 32) | nextU32();
    }

    /// Uniform double in [0, 1), exactly representable (53 random bits).
    double nextDouble() { return static_cast<double>(nextU64() >> 11) * (1.0 / 9007199254740992.0); }

    /// Uniform integer in [0, bound) without modulo bias.
    uint32_t below(uint32_t bound) {
        uint32_t threshold = (~bound + 1u) % bound;
        for (;;) {
            uint32_t r = nextU32();
            if (r >= threshold) return r % bound;
        }
    }

private:
    uint64_t mState = 0;
    uint64_t mInc = 0;
};

} // namespace tessera
