#include "tessera/character/FarMesh.h"

#include <meshoptimizer.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <numeric>
#include <string>

namespace tessera::character {

namespace {

constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();

Status checkInput(const CageMesh& cage, const FarMeshSettings& settings) {
    if (cage.indices.empty() || cage.vertices.empty()) return fail("far mesh: the cage has no triangles");
    if (cage.indices.size() % 3 != 0) {
        return fail("far mesh: the cage has ", std::to_string(cage.indices.size()), " indices, not a multiple of 3");
    }
    for (size_t i = 0; i < cage.indices.size(); ++i) {
        if (cage.indices[i] >= cage.vertices.size()) {
            return fail("far mesh: cage index ", std::to_string(i), " (", std::to_string(cage.indices[i]),
                        ") is beyond the ", std::to_string(cage.vertices.size()), " vertices");
        }
    }
    for (size_t v = 0; v < cage.vertices.size(); ++v) {
        const glm::vec3& p = cage.vertices[v].position;
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
            return fail("far mesh: cage vertex ", std::to_string(v), " has a non-finite position");
        }
    }
    if (settings.targetTriangles == 0) return fail("far mesh: the target triangle count is 0");
    if (!std::isfinite(settings.maxError) || settings.maxError < 0.0f) {
        return fail("far mesh: the maximum error must be finite and non-negative");
    }
    return {};
}

// Keeps only the cage vertices `indices` use, in order of first use, so the
// output does not depend on anything but the index list.
CageMesh compact(const CageMesh& cage, const std::vector<uint32_t>& indices) {
    CageMesh out;
    out.bindings = cage.bindings;
    std::vector<uint32_t> remap(cage.vertices.size(), kNone);
    out.indices.reserve(indices.size());
    for (uint32_t i : indices) {
        if (remap[i] == kNone) {
            remap[i] = static_cast<uint32_t>(out.vertices.size());
            out.vertices.push_back(cage.vertices[i]);
        }
        out.indices.push_back(remap[i]);
    }
    return out;
}

// Seam copies share a position exactly (the generator and glTF exporters copy
// it), so bitwise equality is the right weld; -0 and +0 are one position.
std::array<uint32_t, 3> positionKey(const glm::vec3& p) {
    std::array<uint32_t, 3> key{};
    for (int c = 0; c < 3; ++c) {
        float f = p[c] == 0.0f ? 0.0f : p[c];
        std::memcpy(&key[static_cast<size_t>(c)], &f, sizeof f);
    }
    return key;
}

// The cage with its seam copies welded: one position per distinct location,
// the triangle list over them, each welded vertex's copies (ascending) and
// each cage vertex's UV chart (its connected set of triangles over shared
// vertex indices, named by its smallest vertex).
struct WeldedCage {
    std::vector<glm::vec3> positions;
    std::vector<uint32_t> indices;
    std::vector<std::vector<uint32_t>> copies;
    std::vector<uint32_t> chart;
};

uint32_t findRoot(std::vector<uint32_t>& parent, uint32_t v) {
    while (parent[v] != v) {
        parent[v] = parent[parent[v]];
        v = parent[v];
    }
    return v;
}

WeldedCage weld(const CageMesh& cage) {
    WeldedCage w;
    std::map<std::array<uint32_t, 3>, uint32_t> ids;
    std::vector<uint32_t> weldOf(cage.vertices.size());
    for (size_t v = 0; v < cage.vertices.size(); ++v) {
        auto [it, inserted] = ids.emplace(positionKey(cage.vertices[v].position), static_cast<uint32_t>(w.positions.size()));
        if (inserted) {
            w.positions.push_back(cage.vertices[v].position);
            w.copies.emplace_back();
        }
        weldOf[v] = it->second;
        w.copies[it->second].push_back(static_cast<uint32_t>(v));
    }
    w.indices.reserve(cage.indices.size());
    for (uint32_t i : cage.indices) w.indices.push_back(weldOf[i]);

    std::vector<uint32_t> parent(cage.vertices.size());
    std::iota(parent.begin(), parent.end(), 0u);
    for (size_t t = 0; t < cage.indices.size(); t += 3) {
        for (size_t k = 1; k < 3; ++k) {
            uint32_t a = findRoot(parent, cage.indices[t]), b = findRoot(parent, cage.indices[t + k]);
            // The smaller root wins, so a chart's name does not depend on the union order.
            if (a < b) parent[b] = a;
            else if (b < a) parent[a] = b;
        }
    }
    w.chart.resize(cage.vertices.size());
    for (size_t v = 0; v < cage.vertices.size(); ++v) w.chart[v] = findRoot(parent, static_cast<uint32_t>(v));
    return w;
}

// The copy of welded vertex `u` in `chart`, or kNone.
uint32_t copyInChart(const WeldedCage& w, uint32_t u, uint32_t chart) {
    for (uint32_t v : w.copies[u]) {
        if (w.chart[v] == chart) return v;
    }
    return kNone;
}

// Turns a triangle list over welded vertices back into cage vertices. Each
// triangle takes the UV chart that holds copies of most of its corners, so
// the UVs interpolate inside one chart wherever the simplification allows;
// a corner with no copy there takes its first copy (the triangle is counted
// in `seamTriangles`). Positions, normals and skinning of copies agree, so
// the choice never moves the surface.
std::vector<uint32_t> unweld(const WeldedCage& w, const std::vector<uint32_t>& welded, uint32_t& seamTriangles) {
    std::vector<uint32_t> out(welded.size());
    seamTriangles = 0;
    for (size_t t = 0; t < welded.size(); t += 3) {
        uint32_t bestChart = kNone;
        int bestCount = 0;
        for (size_t k = 0; k < 3; ++k) {
            for (uint32_t v : w.copies[welded[t + k]]) {
                int count = 0;
                for (size_t j = 0; j < 3; ++j) count += copyInChart(w, welded[t + j], w.chart[v]) != kNone ? 1 : 0;
                if (count > bestCount) {
                    bestCount = count;
                    bestChart = w.chart[v];
                }
            }
        }
        if (bestCount < 3) ++seamTriangles;
        for (size_t k = 0; k < 3; ++k) {
            uint32_t v = copyInChart(w, welded[t + k], bestChart);
            out[t + k] = v != kNone ? v : w.copies[welded[t + k]].front();
        }
    }
    return out;
}

// Undirected edges of a welded triangle list not shared by exactly two
// triangles: borders and non-manifold edges. 0 for a closed surface.
size_t openEdges(const std::vector<uint32_t>& indices) {
    std::map<std::pair<uint32_t, uint32_t>, int> uses;
    for (size_t t = 0; t < indices.size(); t += 3) {
        for (size_t k = 0; k < 3; ++k) {
            uint32_t a = indices[t + k], b = indices[t + (k + 1) % 3];
            ++uses[{std::min(a, b), std::max(a, b)}];
        }
    }
    size_t open = 0;
    for (const auto& [edge, count] : uses) open += count != 2 ? 1 : 0;
    return open;
}

} // namespace

const char* farMeshMethodName(FarMeshMethod method) {
    switch (method) {
        case FarMeshMethod::Copy: return "copy";
        case FarMeshMethod::SeamPreserving: return "seam-preserving";
        case FarMeshMethod::Welded: return "welded";
        case FarMeshMethod::Sloppy: return "sloppy";
    }
    return "unknown";
}

Result<FarMesh> simplifyCage(const CageMesh& cage, const FarMeshSettings& settings) {
    if (Status s = checkInput(cage, settings); !s) return s.error();
    FarMesh result;
    if (cage.triangleCount() <= settings.targetTriangles) {
        result.mesh = compact(cage, cage.indices);
        result.cageIndices = cage.indices;
        return result;
    }
    const size_t targetIndices = size_t{settings.targetTriangles} * 3;
    const float scale = meshopt_simplifyScale(&cage.vertices[0].position.x, cage.vertices.size(), sizeof(CageVertex));
    auto finish = [&](FarMeshMethod method, const std::vector<uint32_t>& indices, float error) {
        result.mesh = compact(cage, indices);
        result.cageIndices = indices;
        result.method = method;
        result.relativeError = error;
        result.absoluteError = error * scale;
    };

    // 1. The cage's own vertices: meshoptimizer treats vertices that share a
    // position as seam copies and only collapses them together, along the
    // seam, so charts keep their UVs and the surface keeps no holes. Vertices
    // where three or more charts meet are locked, which on an atlas of many
    // small charts stops this pass well above a few hundred triangles.
    std::vector<uint32_t> indices(cage.indices.size());
    float error = 0.0f;
    indices.resize(meshopt_simplify(indices.data(), cage.indices.data(), cage.indices.size(),
                                    &cage.vertices[0].position.x, cage.vertices.size(), sizeof(CageVertex),
                                    targetIndices, settings.maxError, 0, &error));
    if (!indices.empty() && indices.size() <= targetIndices) {
        finish(FarMeshMethod::SeamPreserving, indices, error);
        return result;
    }

    // 2. Welded positions: no seams, so nothing is locked but real borders;
    // edge collapses on a closed surface keep it closed. The UVs are then
    // picked per triangle from the chart most of its corners belong to.
    WeldedCage welded = weld(cage);
    // Collapses can pinch two close sheets (ears, fingers) into an edge of
    // four triangles. Another collapse order avoids it: a slightly lower
    // target, or an intermediate stop at a multiple of the target (its error
    // then adds to the last stage's). Keep the first result that opens no
    // edge the cage did not have; failing that, the direct one.
    const size_t cageOpen = openEdges(welded.indices);
    std::vector<uint32_t> simplified;
    float weldedError = 0.0f;
    const size_t step = std::max<size_t>(1, settings.targetTriangles / 100) * 3;
    auto simplifyWelded = [&](const std::vector<uint32_t>& in, size_t target, float& stageError) {
        std::vector<uint32_t> out(in.size());
        out.resize(meshopt_simplify(out.data(), in.data(), in.size(), &welded.positions[0].x, welded.positions.size(),
                                    sizeof(glm::vec3), target, settings.maxError, 0, &stageError));
        return out;
    };
    bool clean = false;
    for (size_t ratio : {1u, 2u, 3u, 4u}) {
        if (clean) break;
        // meshoptimizer asserts on a target above the input; no stop needed there.
        if (ratio > 1 && targetIndices * ratio >= welded.indices.size()) break;
        float firstError = 0.0f;
        std::vector<uint32_t> coarse =
            ratio == 1 ? welded.indices : simplifyWelded(welded.indices, targetIndices * ratio, firstError);
        if (ratio > 1 && openEdges(coarse) > cageOpen) continue;
        for (size_t attempt = 0; attempt < 8 && attempt * step < targetIndices; ++attempt) {
            float lastError = 0.0f;
            std::vector<uint32_t> candidate = simplifyWelded(coarse, targetIndices - attempt * step, lastError);
            clean = openEdges(candidate) <= cageOpen;
            if (simplified.empty() || clean) {
                simplified = std::move(candidate);
                weldedError = firstError + lastError;
            }
            if (clean || simplified.size() > targetIndices) break;  // clean, or stopped by the error bound
        }
    }
    if (!simplified.empty() && simplified.size() <= targetIndices) {
        uint32_t seams = 0;
        std::vector<uint32_t> out = unweld(welded, simplified, seams);
        finish(FarMeshMethod::Welded, out, weldedError);
        result.seamTriangles = seams;
        return result;
    }

    // 3. Vertex clustering reaches any target, ignoring topology and the
    // error bound; better a coarse far mesh than none. If even that leaves
    // nothing (a target of a triangle or two), keep the welded pass's result.
    std::vector<uint32_t> sloppy(welded.indices.size());
    float sloppyError = 0.0f;
    sloppy.resize(meshopt_simplifySloppy(sloppy.data(), welded.indices.data(), welded.indices.size(),
                                         &welded.positions[0].x, welded.positions.size(), sizeof(glm::vec3),
                                         targetIndices, std::numeric_limits<float>::max(), &sloppyError));
    FarMeshMethod method = FarMeshMethod::Sloppy;
    if (sloppy.empty()) {
        sloppy = std::move(simplified);
        sloppyError = weldedError;
        method = FarMeshMethod::Welded;
    }
    if (sloppy.empty()) return fail("far mesh: simplification left no triangles");
    uint32_t seams = 0;
    std::vector<uint32_t> out = unweld(welded, sloppy, seams);
    finish(method, out, sloppyError);
    result.seamTriangles = seams;
    return result;
}

} // namespace tessera::character
