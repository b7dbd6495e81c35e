#pragma once
// Seeded procedural noise for the skin detail and colour (internal header).
// Integer hashing instead of permutation tables, so a creature's noise is a
// pure function of (seed, position) with no state to build.

#include <cstdint>
#include <glm/glm.hpp>

namespace tessera::creature::noise {

/// A well-mixed 32-bit hash of a lattice point and a seed.
uint32_t hashLattice(int32_t x, int32_t y, int32_t z, uint32_t seed);

/// Hash to a float in [0, 1).
inline float hashToUnit(uint32_t h) { return static_cast<float>(h >> 8) * (1.0f / 16777216.0f); }

/// Perlin-style gradient noise in about [-1, 1], zero on the lattice.
float gradient(const glm::vec3& p, uint32_t seed);

/// Fractal sum of `octaves` gradient noises, each at twice the frequency and
/// half the amplitude of the last; about [-1, 1].
float fbm(const glm::vec3& p, uint32_t seed, int octaves);

/// Sharp creases: 1 on the zero lines of a gradient noise, falling to 0
/// away from them.
float ridged(const glm::vec3& p, uint32_t seed);

/// Sparse round bumps on a jittered lattice of unit cells: each cell holds
/// a bump with probability `density` at a random point. Returns the height
/// of the tallest bump at p in [0, 1].
float bumps(const glm::vec3& p, uint32_t seed, float density, float minRadius, float maxRadius);

} // namespace tessera::creature::noise
