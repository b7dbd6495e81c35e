#include "TerrainNoise.h"

#include "tessera/core/Random.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace tessera::terrain {
namespace {

// Quintic fade (Perlin 2002): C2-continuous, so slopes and normals of the
// summed noise have no creases along lattice lines.
float fade(float t) { return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f); }

float lerp(float a, float b, float t) { return a + (b - a) * t; }

// floor() for the lattice cell; std::floor is a libm call on baseline x86-64
// (no SSE4.1 rounding instruction) and dominated the noise stage.
int32_t floorToInt(float v) {
    int32_t i = int32_t(v);
    return v < float(i) ? i - 1 : i;
}

// The 8 lattice gradients: axes and diagonals. A table rather than a switch:
// the hash is random, so a switch mispredicts on almost every corner.
constexpr float kGradients[8][2] = {{1, 1}, {-1, 1}, {1, -1}, {-1, -1},
                                    {1, 0}, {-1, 0}, {0, 1},  {0, -1}};

float gradDot(uint32_t hash, float x, float y) {
    const float* g = kGradients[hash & 7u];
    return g[0] * x + g[1] * y;
}

// Moves to the next octave: double the frequency and rotate by atan(3/4)
// (exact float constants 0.8 / 0.6), so that the lattices of successive
// octaves never line up into visible axis-aligned streaks.
glm::vec2 nextOctave(glm::vec2 p, glm::vec2 offset) {
    return glm::vec2(1.6f * p.x - 1.2f * p.y, 1.2f * p.x + 1.6f * p.y) + offset;
}

} // namespace

TerrainNoise::TerrainNoise(uint64_t seed) {
    Random random(seed, 0x5eed'7e44'a1ULL);
    for (uint32_t k = 0; k < 256; ++k) mPerm[k] = uint8_t(k);
    // Fisher-Yates with Random::below: the permutation depends only on the seed.
    for (uint32_t k = 255; k > 0; --k) std::swap(mPerm[k], mPerm[random.below(k + 1)]);
    for (uint32_t k = 0; k < 256; ++k) mPerm[256 + k] = mPerm[k];
    for (float& v : mValues) v = random.range(-1.0f, 1.0f);
    for (glm::vec2& o : mOffsets) o = glm::vec2(random.range(0.0f, 256.0f), random.range(0.0f, 256.0f));
}

uint32_t TerrainNoise::hash(int32_t x, int32_t y) const {
    return mPerm[(uint32_t(mPerm[uint32_t(x) & 255u]) + uint32_t(y)) & 255u];
}

float TerrainNoise::gradient(glm::vec2 p) const {
    int32_t x = floorToInt(p.x), y = floorToInt(p.y);
    float dx = p.x - float(x), dy = p.y - float(y);
    float n00 = gradDot(hash(x, y), dx, dy);
    float n10 = gradDot(hash(x + 1, y), dx - 1.0f, dy);
    float n01 = gradDot(hash(x, y + 1), dx, dy - 1.0f);
    float n11 = gradDot(hash(x + 1, y + 1), dx - 1.0f, dy - 1.0f);
    float u = fade(dx), v = fade(dy);
    // Raw 2D Perlin noise rarely leaves [-0.65, 0.65]; stretch it so that
    // ridges (1 - |n|) span the whole [0, 1] range.
    return std::clamp(1.5f * lerp(lerp(n00, n10, u), lerp(n01, n11, u), v), -1.0f, 1.0f);
}

float TerrainNoise::value(glm::vec2 p) const {
    int32_t x = floorToInt(p.x), y = floorToInt(p.y);
    float u = fade(p.x - float(x)), v = fade(p.y - float(y));
    float a = lerp(mValues[hash(x, y)], mValues[hash(x + 1, y)], u);
    float b = lerp(mValues[hash(x, y + 1)], mValues[hash(x + 1, y + 1)], u);
    return lerp(a, b, v);
}

float TerrainNoise::fbmGradient(glm::vec2 p, int octaves) const {
    assert(octaves > 0 && octaves <= int(mOffsets.size()));
    float sum = 0.0f, amplitude = 1.0f, total = 0.0f;
    for (int k = 0; k < octaves; ++k) {
        sum += amplitude * gradient(p);
        total += amplitude;
        amplitude *= 0.5f;
        p = nextOctave(p, mOffsets[k]);
    }
    return sum / total;
}

float TerrainNoise::fbmValue(glm::vec2 p, int octaves) const {
    assert(octaves > 0 && octaves <= int(mOffsets.size()));
    float sum = 0.0f, amplitude = 1.0f, total = 0.0f;
    for (int k = 0; k < octaves; ++k) {
        sum += amplitude * value(p);
        total += amplitude;
        amplitude *= 0.5f;
        p = nextOctave(p, mOffsets[k]);
    }
    return sum / total;
}

float TerrainNoise::ridged(glm::vec2 p, int octaves) const {
    assert(octaves > 0 && octaves <= int(mOffsets.size()));
    // 1 - |n| has a crease wherever the noise crosses zero. On the low octaves
    // those creases trace long smooth arcs that read as artificial folds, so
    // |n| is softened to sqrt(n^2 + e) with e shrinking fourfold per octave:
    // broad rounded massifs at the bottom, knife-edge crests at the top.
    float softness = 0.05f;
    auto ridge = [&softness](float n) {
        float s = std::max(0.0f, 1.0f - std::sqrt(n * n + softness));
        return s * s;
    };
    float signal = ridge(gradient(p));
    // H = 1 with lacunarity 2 makes the octave weights exact powers of two,
    // so no pow() (whose last bit varies between libms) is needed.
    float sum = signal, amplitude = 1.0f, total = 1.0f;
    for (int k = 1; k < octaves; ++k) {
        p = nextOctave(p, mOffsets[k - 1]);
        amplitude *= 0.5f;
        softness *= 0.25f;
        // Detail where the previous octave is high (on the ridges) and little
        // in the valleys: the heterogeneity that makes it look eroded.
        float weight = std::clamp(signal * 2.0f, 0.0f, 1.0f);
        signal = ridge(gradient(p)) * weight;
        sum += signal * amplitude;
        total += amplitude;
    }
    return sum / total;
}

} // namespace tessera::terrain
