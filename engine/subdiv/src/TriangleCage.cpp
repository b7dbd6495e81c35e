#include "tessera/subdiv/TriangleCage.h"

#include <bit>
#include <cmath>
#include <string>
#include <unordered_map>

namespace tessera::subdiv {

namespace {

struct PositionKey {
    uint32_t x, y, z;
    bool operator==(const PositionKey&) const = default;
};

struct PositionKeyHash {
    size_t operator()(const PositionKey& k) const {
        uint64_t h = (uint64_t(k.x) * 0x9E3779B97F4A7C15ull) ^ (uint64_t(k.y) * 0xC2B2AE3D27D4EB4Full) ^
                     (uint64_t(k.z) * 0x165667B19E3779F9ull);
        return size_t(h ^ (h >> 29));
    }
};

// +0.0f folds -0.0f into 0.0f, so a seam's two copies of a point on an axis
// plane weld even when one side was computed as -0.
PositionKey keyOf(glm::vec3 p) {
    return {std::bit_cast<uint32_t>(p.x + 0.0f), std::bit_cast<uint32_t>(p.y + 0.0f),
            std::bit_cast<uint32_t>(p.z + 0.0f)};
}

void hashWord(uint64_t& h, uint32_t word) {
    for (int b = 0; b < 4; ++b) {
        h ^= (word >> (8 * b)) & 0xffu;
        h *= 0x100000001B3ull;
    }
}

} // namespace

Result<WeldedCage> weldTriangleCage(std::span<const glm::vec3> positions, std::span<const uint32_t> indices,
                                    const std::string& name) {
    if (indices.empty()) return fail(name, ": the cage has no triangles");
    if (indices.size() % 3 != 0)
        return fail(name, ": the cage has ", std::to_string(indices.size()), " indices, not a multiple of 3");
    WeldedCage cage;
    cage.shape.name = name;
    cage.controlOf.assign(positions.size(), 0xffffffffu);
    std::unordered_map<PositionKey, uint32_t, PositionKeyHash> welded;
    for (uint32_t v = 0; v < positions.size(); ++v) {
        const glm::vec3 p = positions[v];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            return fail(name, ": cage vertex ", std::to_string(v), " has a non-finite position");
        auto [it, added] = welded.try_emplace(keyOf(p), uint32_t(cage.shape.positions.size()));
        if (added) {
            cage.shape.positions.push_back(p);
            cage.firstCageVertex.push_back(v);
        }
        cage.controlOf[v] = it->second;
    }
    const uint32_t triangles = uint32_t(indices.size() / 3);
    cage.shape.faceSizes.assign(triangles, 3u);
    cage.shape.faceVertices.reserve(indices.size());
    cage.topologyHash = 0xCBF29CE484222325ull;
    hashWord(cage.topologyHash, uint32_t(cage.shape.positions.size()));
    for (uint32_t t = 0; t < triangles; ++t) {
        uint32_t c[3];
        for (int k = 0; k < 3; ++k) {
            const uint32_t index = indices[3 * t + k];
            if (index >= positions.size())
                return fail(name, ": cage triangle ", std::to_string(t), " names vertex ", std::to_string(index), " of ",
                            std::to_string(positions.size()));
            c[k] = cage.controlOf[index];
        }
        if (c[0] == c[1] || c[1] == c[2] || c[0] == c[2])
            return fail(name, ": cage triangle ", std::to_string(t), " is degenerate once its positions are welded");
        for (uint32_t k : c) {
            cage.shape.faceVertices.push_back(k);
            hashWord(cage.topologyHash, k);
        }
    }
    cage.shape.boundary = BoundaryInterpolation::EdgeAndCorner;
    return cage;
}

} // namespace tessera::subdiv
