#pragma once
/// @file TerrainNoise.h
/// Internal: seeded 2D gradient and value noise with fBm and ridged
/// multifractal sums, for the height-map generator.

#include <array>
#include <cstdint>

#include <glm/vec2.hpp>

namespace tessera::terrain {

/// Lattice noise over a 256-periodic integer grid, seeded through a
/// tessera::Random-shuffled permutation. Pure functions of the position after
/// construction, so safe to call from many threads at once.
class TerrainNoise {
public:
    explicit TerrainNoise(uint64_t seed);

    /// Perlin gradient noise with 8 gradient directions, scaled to fill [-1, 1]
    /// (|n| has a median of about 0.27).
    float gradient(glm::vec2 p) const;
    /// Value noise (random lattice values, quintic interpolation), in [-1, 1].
    float value(glm::vec2 p) const;

    /// Fractional Brownian motion of gradient noise: octaves of doubling
    /// frequency and halving amplitude, divided by the amplitude sum so the
    /// result stays roughly in [-1, 1].
    float fbmGradient(glm::vec2 p, int octaves) const;
    /// The same sum over value noise, in [-1, 1].
    float fbmValue(glm::vec2 p, int octaves) const;

    /// Musgrave's ridged multifractal (offset 1, gain 2, H = 1): sharp crests
    /// where the noise crosses zero, each octave weighted by the one before so
    /// that detail gathers on the ridges and valleys stay smooth. About [0, 1].
    float ridged(glm::vec2 p, int octaves) const;

private:
    uint32_t hash(int32_t x, int32_t y) const;

    std::array<uint8_t, 512> mPerm{};    ///< Permutation of 0..255, stored twice.
    std::array<float, 256> mValues{};    ///< Lattice values for value noise.
    std::array<glm::vec2, 16> mOffsets{}; ///< Per-octave shifts that decorrelate octaves.
};

} // namespace tessera::terrain
