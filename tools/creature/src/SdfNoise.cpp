#include "SdfNoise.h"

#include <algorithm>
#include <cmath>

namespace tessera::creature::noise {

uint32_t hashLattice(int32_t x, int32_t y, int32_t z, uint32_t seed) {
    // Murmur3-style finalisation over a linear combination: cheap, and
    // neighbouring lattice points give unrelated values.
    uint32_t h = seed * 0x9E3779B1u;
    h ^= static_cast<uint32_t>(x) * 0x85EBCA77u;
    h = (h << 13) | (h >> 19);
    h ^= static_cast<uint32_t>(y) * 0xC2B2AE3Du;
    h = (h << 13) | (h >> 19);
    h ^= static_cast<uint32_t>(z) * 0x27D4EB2Fu;
    h ^= h >> 16;
    h *= 0x85EBCA6Bu;
    h ^= h >> 13;
    h *= 0xC2B2AE35u;
    h ^= h >> 16;
    return h;
}

namespace {

float fade(float t) { return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f); }

float cornerDot(int32_t x, int32_t y, int32_t z, uint32_t seed, float dx, float dy, float dz) {
    // The 12 cube-edge directions, as in improved Perlin noise.
    switch (hashLattice(x, y, z, seed) % 12u) {
    case 0: return dx + dy;
    case 1: return -dx + dy;
    case 2: return dx - dy;
    case 3: return -dx - dy;
    case 4: return dx + dz;
    case 5: return -dx + dz;
    case 6: return dx - dz;
    case 7: return -dx - dz;
    case 8: return dy + dz;
    case 9: return -dy + dz;
    case 10: return dy - dz;
    default: return -dy - dz;
    }
}

} // namespace

float gradient(const glm::vec3& p, uint32_t seed) {
    glm::vec3 f = glm::floor(p);
    auto x = static_cast<int32_t>(f.x), y = static_cast<int32_t>(f.y), z = static_cast<int32_t>(f.z);
    glm::vec3 d = p - f;
    float u = fade(d.x), v = fade(d.y), w = fade(d.z);
    auto lerp = [](float a, float b, float t) { return a + (b - a) * t; };
    float x00 = lerp(cornerDot(x, y, z, seed, d.x, d.y, d.z), cornerDot(x + 1, y, z, seed, d.x - 1, d.y, d.z), u);
    float x10 = lerp(cornerDot(x, y + 1, z, seed, d.x, d.y - 1, d.z),
                     cornerDot(x + 1, y + 1, z, seed, d.x - 1, d.y - 1, d.z), u);
    float x01 = lerp(cornerDot(x, y, z + 1, seed, d.x, d.y, d.z - 1),
                     cornerDot(x + 1, y, z + 1, seed, d.x - 1, d.y, d.z - 1), u);
    float x11 = lerp(cornerDot(x, y + 1, z + 1, seed, d.x, d.y - 1, d.z - 1),
                     cornerDot(x + 1, y + 1, z + 1, seed, d.x - 1, d.y - 1, d.z - 1), u);
    return lerp(lerp(x00, x10, v), lerp(x01, x11, v), w);
}

float fbm(const glm::vec3& p, uint32_t seed, int octaves) {
    float sum = 0.0f, amplitude = 0.5f, norm = 0.0f;
    glm::vec3 q = p;
    for (int i = 0; i < octaves; ++i) {
        sum += amplitude * gradient(q, seed + static_cast<uint32_t>(i) * 101u);
        norm += amplitude;
        amplitude *= 0.5f;
        q = q * 2.03f + glm::vec3(17.1f, 3.7f, 9.3f);
    }
    return sum / norm;
}

float ridged(const glm::vec3& p, uint32_t seed) {
    float r = 1.0f - std::min(1.0f, std::abs(gradient(p, seed)) * 2.5f);
    return r * r * r;
}

float bumps(const glm::vec3& p, uint32_t seed, float density, float minRadius, float maxRadius) {
    glm::vec3 f = glm::floor(p);
    auto cx = static_cast<int32_t>(f.x), cy = static_cast<int32_t>(f.y), cz = static_cast<int32_t>(f.z);
    float best = 0.0f;
    for (int32_t z = cz - 1; z <= cz + 1; ++z) {
        for (int32_t y = cy - 1; y <= cy + 1; ++y) {
            for (int32_t x = cx - 1; x <= cx + 1; ++x) {
                uint32_t h = hashLattice(x, y, z, seed);
                if (hashToUnit(h) >= density) continue;
                glm::vec3 centre(static_cast<float>(x) + hashToUnit(hashLattice(x, y, z, seed + 1u)),
                                 static_cast<float>(y) + hashToUnit(hashLattice(x, y, z, seed + 2u)),
                                 static_cast<float>(z) + hashToUnit(hashLattice(x, y, z, seed + 3u)));
                float radius = minRadius + (maxRadius - minRadius) * hashToUnit(hashLattice(x, y, z, seed + 4u));
                glm::vec3 d = p - centre;
                float t = glm::dot(d, d) / (radius * radius);
                if (t >= 1.0f) continue;
                float s = 1.0f - t;
                best = std::max(best, s * s);
            }
        }
    }
    return best;
}

} // namespace tessera::creature::noise
