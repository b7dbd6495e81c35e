#pragma once
// Meshes with known answers for the displacement baker tests: a UV-charted
// cube cage, a flat cage, the cage's own subdivision displaced along its
// interpolated normal, height-field sculpts, and the shader's decode/fetch.

#include "creature/DisplacementBaker.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace tessera::creature::baketest {

using character::CageMesh;
using character::CageVertex;

inline constexpr float kAtlasMargin = 0.03f;

struct CubeFace {
    glm::vec3 n, u, v;  // u x v = n: counter-clockwise seen from outside
    int col, row;       // atlas cell (3 x 2)
};
inline const CubeFace kFaces[6] = {
    {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}, 0, 0},  {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}, 1, 0},
    {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}, 2, 0},  {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}, 0, 1},
    {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}, 1, 1},   {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}, 2, 1},
};

/// Face-local coordinate k of n in [-0.5, 0.5], exactly antisymmetric so
/// neighbouring faces produce bit-identical edge positions.
inline float gridCoord(int k, int n) { return static_cast<float>(2 * k - n) / static_cast<float>(2 * n); }

inline glm::vec2 atlasUv(const CubeFace& f, float s, float t) {
    const float cw = 1.0f / 3.0f, ch = 0.5f;
    return {f.col * cw + kAtlasMargin + s * (cw - 2 * kAtlasMargin), f.row * ch + kAtlasMargin + t * (ch - 2 * kAtlasMargin)};
}

/// A unit cube centred at the origin, n x n quads per face, radial normals.
inline CageMesh makeCubeCage(int n) {
    CageMesh cage;
    for (const CubeFace& f : kFaces) {
        uint32_t base = static_cast<uint32_t>(cage.vertices.size());
        for (int j = 0; j <= n; ++j) {
            for (int i = 0; i <= n; ++i) {
                CageVertex v;
                v.position = 0.5f * f.n + gridCoord(i, n) * f.u + gridCoord(j, n) * f.v;
                v.normal = glm::normalize(v.position);
                v.tangent = glm::vec4(f.u, 1.0f);
                v.uv = atlasUv(f, static_cast<float>(i) / n, static_cast<float>(j) / n);
                cage.vertices.push_back(v);
            }
        }
        auto at = [&](int i, int j) { return base + static_cast<uint32_t>(j * (n + 1) + i); };
        for (int j = 0; j < n; ++j) {
            for (int i = 0; i < n; ++i) {
                cage.indices.insert(cage.indices.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1)});
                cage.indices.insert(cage.indices.end(), {at(i, j), at(i + 1, j + 1), at(i, j + 1)});
            }
        }
    }
    return cage;
}

/// A flat square cage over [0,1]^2 at z = 0, uv = (x, y), normal +Z.
inline CageMesh makePlaneCage(int n) {
    CageMesh cage;
    for (int j = 0; j <= n; ++j) {
        for (int i = 0; i <= n; ++i) {
            CageVertex v;
            v.uv = {static_cast<float>(i) / n, static_cast<float>(j) / n};
            v.position = {v.uv, 0.0f};
            v.normal = {0, 0, 1};
            cage.vertices.push_back(v);
        }
    }
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            uint32_t a = static_cast<uint32_t>(j * (n + 1) + i), b = a + 1, c = a + n + 2, d = a + n + 1;
            cage.indices.insert(cage.indices.end(), {a, b, c, a, c, d});
        }
    }
    return cage;
}

inline float field(const glm::vec3& p) {
    return 0.02f * (std::sin(5.0f * p.x + 1.0f) * std::cos(4.0f * p.y) + 0.5f * std::sin(6.0f * p.z + 0.3f));
}

/// Each cage triangle subdivided m times per edge and displaced by
/// `displace(P)` along the normalised interpolated cage normal.
template <class Fn>
SculptMesh subdivideCage(const CageMesh& cage, int m, Fn displace) {
    SculptMesh sculpt;
    for (uint32_t t = 0; t < cage.triangleCount(); ++t) {
        const CageVertex* v[3] = {&cage.vertices[cage.indices[3 * t]], &cage.vertices[cage.indices[3 * t + 1]],
                                  &cage.vertices[cage.indices[3 * t + 2]]};
        uint32_t base = static_cast<uint32_t>(sculpt.positions.size());
        std::vector<uint32_t> row(static_cast<size_t>(m + 2), 0);
        for (int j = 0; j <= m; ++j) {
            for (int i = 0; i + j <= m; ++i) {
                // Integer ratios, so points on a shared edge are bit-identical in both triangles.
                float b1 = static_cast<float>(i) / m, b2 = static_cast<float>(j) / m;
                float b0 = static_cast<float>(m - i - j) / m;
                glm::vec3 p = b0 * v[0]->position + b1 * v[1]->position + b2 * v[2]->position;
                glm::vec3 n = glm::normalize(b0 * v[0]->normal + b1 * v[1]->normal + b2 * v[2]->normal);
                sculpt.positions.push_back(p + displace(p) * n);
            }
        }
        auto at = [&](int i, int j) { return base + static_cast<uint32_t>(j * (m + 1) - j * (j - 1) / 2 + i); };
        for (int j = 0; j < m; ++j) {
            for (int i = 0; i + j < m; ++i) {
                sculpt.indices.insert(sculpt.indices.end(), {at(i, j), at(i + 1, j), at(i, j + 1)});
                if (i + j + 1 < m) sculpt.indices.insert(sculpt.indices.end(), {at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
            }
        }
    }
    return sculpt;
}

/// A flat grid sculpt over [x0,x1] x [y0,y1] with z = height(x, y).
template <class Fn>
SculptMesh makeHeightSculpt(float x0, float x1, float y0, float y1, int n, Fn height) {
    SculptMesh sculpt;
    for (int j = 0; j <= n; ++j) {
        for (int i = 0; i <= n; ++i) {
            float x = x0 + (x1 - x0) * i / n, y = y0 + (y1 - y0) * j / n;
            sculpt.positions.push_back({x, y, height(x, y)});
        }
    }
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            uint32_t a = static_cast<uint32_t>(j * (n + 1) + i), b = a + 1, c = a + n + 2, d = a + n + 1;
            sculpt.indices.insert(sculpt.indices.end(), {a, b, c, a, c, d});
        }
    }
    return sculpt;
}

/// The map as the shader reads it: sample * scale + bias per texel.
inline std::vector<float> decode(const character::DisplacementMap& map) {
    std::vector<float> out(map.image.width * map.image.height);
    for (size_t i = 0; i < out.size(); ++i) {
        uint16_t s = static_cast<uint16_t>(map.image.bytes[2 * i] | (map.image.bytes[2 * i + 1] << 8));
        out[i] = static_cast<float>(s) / 65535.0f * map.scale + map.bias;
    }
    return out;
}

inline float fetch(const std::vector<float>& texels, uint32_t size, glm::vec2 uv) {
    float x = uv.x * size - 0.5f, y = uv.y * size - 0.5f;
    int ix = static_cast<int>(std::floor(x)), iy = static_cast<int>(std::floor(y));
    float fx = x - ix, fy = y - iy;
    auto at = [&](int a, int b) {
        a = std::clamp(a, 0, static_cast<int>(size) - 1);
        b = std::clamp(b, 0, static_cast<int>(size) - 1);
        return texels[static_cast<size_t>(b) * size + static_cast<size_t>(a)];
    };
    return (1 - fx) * (1 - fy) * at(ix, iy) + fx * (1 - fy) * at(ix + 1, iy) + (1 - fx) * fy * at(ix, iy + 1) +
           fx * fy * at(ix + 1, iy + 1);
}

} // namespace tessera::creature::baketest
