#include "MarchingTetrahedra.h"

#include "tessera/core/ParallelFor.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>

namespace tessera::creature {

namespace {

constexpr int kBlock = 4;  // fine cells per coarse block

// The six tetrahedra of the Kuhn triangulation: one per axis order, walking
// from corner (0,0,0) to (1,1,1). Every edge steps by a 0/1 vector from the
// lower-numbered vertex, which keys shared edge vertices.
constexpr int kAxisOrders[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};

struct Grid {
    int nx, ny, nz;
    size_t index(int x, int y, int z) const {
        return (static_cast<size_t>(z) * static_cast<size_t>(ny) + static_cast<size_t>(y)) * static_cast<size_t>(nx) +
               static_cast<size_t>(x);
    }
};

} // namespace

IndexedMesh marchTetrahedra(const std::function<float(const glm::vec3&)>& field, const glm::vec3& lo,
                            const glm::vec3& hi, float cell, const std::function<void(float)>& progress) {
    glm::ivec3 cells = glm::ivec3(glm::ceil((hi - lo) / cell));
    Grid g{cells.x + 1, cells.y + 1, cells.z + 1};
    auto pos = [&](int x, int y, int z) {
        return lo + glm::vec3(static_cast<float>(x), static_cast<float>(y), static_cast<float>(z)) * cell;
    };

    // Coarse pass: which blocks can hold surface at all.
    Grid cg{cells.x / kBlock + 2, cells.y / kBlock + 2, cells.z / kBlock + 2};
    std::vector<float> coarse(cg.index(0, 0, cg.nz));
    core::parallelForRanges(uint32_t(coarse.size()), 256, 0, [&](core::IndexRange range) {
        const size_t begin = range.begin, end = range.end;
        for (size_t i = begin; i < end; ++i) {
            int x = static_cast<int>(i % static_cast<size_t>(cg.nx));
            int y = static_cast<int>((i / static_cast<size_t>(cg.nx)) % static_cast<size_t>(cg.ny));
            int z = static_cast<int>(i / (static_cast<size_t>(cg.nx) * static_cast<size_t>(cg.ny)));
            coarse[i] = field(pos(x * kBlock, y * kBlock, z * kBlock));
        }
    });
    // Generous: the field is only roughly a Euclidean distance.
    const float margin = 2.0f * std::sqrt(3.0f) * static_cast<float>(kBlock) * cell;
    auto blockValue = [&](int bx, int by, int bz, float* sign) {
        float first = coarse[cg.index(bx, by, bz)];
        for (int c = 0; c < 8; ++c) {
            float v = coarse[cg.index(bx + (c & 1), by + ((c >> 1) & 1), bz + ((c >> 2) & 1))];
            if (std::abs(v) < margin || (v < 0.0f) != (first < 0.0f)) return false;
        }
        *sign = first;
        return true;
    };
    if (progress) progress(0.1f);

    std::vector<float> values(g.index(0, 0, g.nz));
    size_t rows = static_cast<size_t>(g.ny) * static_cast<size_t>(g.nz);
    core::parallelForRanges(uint32_t(rows), 1, 0, [&](core::IndexRange range) {
        const size_t begin = range.begin, end = range.end;
        for (size_t r = begin; r < end; ++r) {
            int y = static_cast<int>(r % static_cast<size_t>(g.ny)), z = static_cast<int>(r / static_cast<size_t>(g.ny));
            for (int x = 0; x < g.nx; ++x) {
                float far = 0.0f;
                bool skip = blockValue(x / kBlock, y / kBlock, z / kBlock, &far);
                values[g.index(x, y, z)] = skip ? far : field(pos(x, y, z));
            }
        }
    });
    if (progress) progress(0.6f);

    IndexedMesh mesh;
    std::unordered_map<uint64_t, uint32_t> edgeVertex;
    auto vertexOn = [&](const glm::ivec3& a, const glm::ivec3& b, float fa, float fb) {
        glm::ivec3 d = b - a;
        uint64_t key = static_cast<uint64_t>(g.index(a.x, a.y, a.z)) * 8u +
                       static_cast<uint64_t>(d.x | (d.y << 1) | (d.z << 2));
        auto [it, inserted] = edgeVertex.try_emplace(key, static_cast<uint32_t>(mesh.positions.size()));
        if (inserted) {
            // Keep vertices strictly inside their edge so no two coincide.
            float t = std::clamp(fa / (fa - fb), 1e-3f, 1.0f - 1e-3f);
            glm::vec3 pa = pos(a.x, a.y, a.z), pb = pos(b.x, b.y, b.z);
            mesh.positions.push_back(pa + (pb - pa) * t);
        }
        return it->second;
    };
    auto emit = [&](uint32_t i0, uint32_t i1, uint32_t i2, const glm::vec3& outward) {
        const glm::vec3 &a = mesh.positions[i0], &b = mesh.positions[i1], &c = mesh.positions[i2];
        // The triangle lies on a level set of the tetrahedron's linear
        // interpolant, so its normal is parallel to `outward`'s true gradient.
        if (glm::dot(glm::cross(b - a, c - a), outward) < 0.0f) std::swap(i1, i2);
        mesh.indices.insert(mesh.indices.end(), {i0, i1, i2});
    };

    for (int z = 0; z + 1 < g.nz; ++z) {
        for (int y = 0; y + 1 < g.ny; ++y) {
            for (int x = 0; x + 1 < g.nx; ++x) {
                int inside = 0;
                for (int c = 0; c < 8; ++c)
                    inside += values[g.index(x + (c & 1), y + ((c >> 1) & 1), z + ((c >> 2) & 1))] < 0.0f;
                if (inside == 0 || inside == 8) continue;
                for (const auto& order : kAxisOrders) {
                    std::array<glm::ivec3, 4> v;
                    v[0] = glm::ivec3(x, y, z);
                    for (int k = 0; k < 3; ++k) {
                        v[k + 1] = v[k];
                        v[k + 1][order[k]] += 1;
                    }
                    std::array<float, 4> f;
                    int in[4], out[4], nin = 0, nout = 0;
                    glm::vec3 cin(0.0f), cout(0.0f);
                    for (int k = 0; k < 4; ++k) {
                        f[k] = values[g.index(v[k].x, v[k].y, v[k].z)];
                        glm::vec3 p = pos(v[k].x, v[k].y, v[k].z);
                        if (f[k] < 0.0f) { in[nin++] = k; cin += p; } else { out[nout++] = k; cout += p; }
                    }
                    if (nin == 0 || nout == 0) continue;
                    glm::vec3 outward = cout / static_cast<float>(nout) - cin / static_cast<float>(nin);
                    auto ev = [&](int i, int j) {
                        return i < j ? vertexOn(v[i], v[j], f[i], f[j]) : vertexOn(v[j], v[i], f[j], f[i]);
                    };
                    if (nin == 1 || nout == 1) {
                        int apex = nin == 1 ? in[0] : out[0];
                        const int* rest = nin == 1 ? out : in;
                        emit(ev(apex, rest[0]), ev(apex, rest[1]), ev(apex, rest[2]), outward);
                    } else {
                        uint32_t q0 = ev(in[0], out[0]), q1 = ev(in[0], out[1]);
                        uint32_t q2 = ev(in[1], out[1]), q3 = ev(in[1], out[0]);
                        emit(q0, q1, q2, outward);
                        emit(q0, q2, q3, outward);
                    }
                }
            }
        }
        if (progress && (z & 15) == 0) progress(0.6f + 0.4f * static_cast<float>(z) / static_cast<float>(g.nz));
    }
    if (progress) progress(1.0f);
    return mesh;
}

} // namespace tessera::creature
