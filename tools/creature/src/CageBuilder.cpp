#include "CageBuilder.h"

#include <meshoptimizer.h>

#include <algorithm>
#include <map>
#include <numeric>

namespace tessera::creature {

namespace {

uint32_t findRoot(std::vector<uint32_t>& parent, uint32_t x) {
    while (parent[x] != x) {
        parent[x] = parent[parent[x]];
        x = parent[x];
    }
    return x;
}

IndexedMesh compact(const std::vector<glm::vec3>& positions, const std::vector<uint32_t>& indices) {
    IndexedMesh out;
    std::vector<uint32_t> remap(positions.size(), UINT32_MAX);
    out.indices.reserve(indices.size());
    for (uint32_t i : indices) {
        if (remap[i] == UINT32_MAX) {
            remap[i] = static_cast<uint32_t>(out.positions.size());
            out.positions.push_back(positions[i]);
        }
        out.indices.push_back(remap[i]);
    }
    return out;
}

} // namespace

IndexedMesh keepLargestComponent(const IndexedMesh& mesh) {
    std::vector<uint32_t> parent(mesh.positions.size());
    std::iota(parent.begin(), parent.end(), 0u);
    for (size_t t = 0; t < mesh.indices.size(); t += 3) {
        uint32_t a = findRoot(parent, mesh.indices[t]);
        for (int k = 1; k < 3; ++k) {
            uint32_t b = findRoot(parent, mesh.indices[t + static_cast<size_t>(k)]);
            if (a != b) parent[std::max(a, b)] = std::min(a, b);
            a = std::min(a, b);
        }
    }
    std::vector<uint32_t> triangles(mesh.positions.size(), 0);
    for (size_t t = 0; t < mesh.indices.size(); t += 3) ++triangles[findRoot(parent, mesh.indices[t])];
    uint32_t best = static_cast<uint32_t>(std::max_element(triangles.begin(), triangles.end()) - triangles.begin());
    std::vector<uint32_t> kept;
    for (size_t t = 0; t < mesh.indices.size(); t += 3) {
        if (findRoot(parent, mesh.indices[t]) == best)
            kept.insert(kept.end(), mesh.indices.begin() + static_cast<long>(t), mesh.indices.begin() + static_cast<long>(t) + 3);
    }
    return compact(mesh.positions, kept);
}

namespace {

IndexedMesh simplifyOnce(const IndexedMesh& mesh, size_t targetTriangles) {
    std::vector<uint32_t> out(mesh.indices.size());
    float error = 0.0f;
    size_t count = meshopt_simplify(out.data(), mesh.indices.data(), mesh.indices.size(), &mesh.positions[0].x,
                                    mesh.positions.size(), sizeof(glm::vec3), targetTriangles * 3, 1.0f, 0, &error);
    out.resize(count);
    return compact(mesh.positions, out);
}

} // namespace

IndexedMesh simplifyMesh(const IndexedMesh& mesh, uint32_t targetTriangles) {
    // Edge collapses can, rarely, pinch two close sheets (an ear, a finger)
    // into a non-manifold edge. Simplify most of the way once, then try the
    // last step with slightly different targets until the result is clean;
    // if the intermediate mesh is already pinched, redo it at another
    // ratio. Deterministic, and cheap in the common case.
    IndexedMesh best;
    for (size_t ratio : {4u, 6u}) {
        IndexedMesh coarse = mesh.triangleCount() > targetTriangles * ratio
                                 ? simplifyOnce(mesh, size_t{targetTriangles} * ratio)
                                 : mesh;
        if (countTopologyDefects(coarse) != 0) continue;
        for (uint32_t attempt = 0; attempt < 8; ++attempt) {
            size_t target = targetTriangles + attempt * (targetTriangles / 500u + 2u);
            IndexedMesh result = simplifyOnce(coarse, target);
            if (countTopologyDefects(result) == 0) return result;
            if (best.indices.empty()) best = std::move(result);
        }
    }
    // Every variant pinched: the caller re-extracts on a shifted grid.
    return best.indices.empty() ? simplifyOnce(mesh, targetTriangles) : best;
}

size_t countTopologyDefects(const IndexedMesh& mesh) {
    // Each directed edge must appear once and its reverse once.
    std::map<std::pair<uint32_t, uint32_t>, int> directed;
    size_t defects = 0;
    for (size_t t = 0; t < mesh.indices.size(); t += 3) {
        for (int k = 0; k < 3; ++k) {
            uint32_t a = mesh.indices[t + static_cast<size_t>(k)], b = mesh.indices[t + static_cast<size_t>((k + 1) % 3)];
            if (a == b) ++defects;
            ++directed[{a, b}];
        }
    }
    for (const auto& [edge, count] : directed) {
        auto reverse = directed.find({edge.second, edge.first});
        if (count != 1 || reverse == directed.end() || reverse->second != 1) ++defects;
    }
    return defects;
}

std::vector<glm::vec3> areaWeightedNormals(const IndexedMesh& mesh) {
    std::vector<glm::vec3> normals(mesh.positions.size(), glm::vec3(0.0f));
    for (size_t t = 0; t < mesh.indices.size(); t += 3) {
        uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
        // The cross product's length is twice the area: the weighting is free.
        glm::vec3 n = glm::cross(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a]);
        normals[a] += n;
        normals[b] += n;
        normals[c] += n;
    }
    for (glm::vec3& n : normals) {
        float len = glm::length(n);
        n = len > 1e-20f ? n / len : glm::vec3(0.0f, 1.0f, 0.0f);
    }
    return normals;
}

} // namespace tessera::creature
