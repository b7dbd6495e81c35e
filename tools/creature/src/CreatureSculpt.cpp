#include "CreatureSculpt.h"

#include "tessera/core/ParallelFor.h"

#include <algorithm>
#include <unordered_map>

namespace tessera::creature {

namespace {

// One level of midpoint subdivision. Midpoint indices follow the triangle
// order, so the result is deterministic; the map is only looked up.
void subdivide(std::vector<glm::vec3>& positions, std::vector<uint32_t>& indices) {
    std::unordered_map<uint64_t, uint32_t> midpoints;
    midpoints.reserve(indices.size());
    auto mid = [&](uint32_t a, uint32_t b) {
        uint64_t key = (static_cast<uint64_t>(std::min(a, b)) << 32) | std::max(a, b);
        auto [it, inserted] = midpoints.try_emplace(key, static_cast<uint32_t>(positions.size()));
        if (inserted) positions.push_back((positions[a] + positions[b]) * 0.5f);
        return it->second;
    };
    std::vector<uint32_t> out;
    out.reserve(indices.size() * 4);
    for (size_t t = 0; t < indices.size(); t += 3) {
        uint32_t a = indices[t], b = indices[t + 1], c = indices[t + 2];
        uint32_t ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
        out.insert(out.end(), {a, ab, ca, ab, b, bc, ca, bc, c, ab, bc, ca});
    }
    indices = std::move(out);
}

} // namespace

SculptMesh makeSculpt(const IndexedMesh& cage, const CreatureSdf& sdf, const SkinDetail& skin, uint32_t minTriangles,
                      const std::function<void(float)>& progress) {
    SculptMesh sculpt;
    sculpt.positions = cage.positions;
    sculpt.indices = cage.indices;
    while (sculpt.triangleCount() < minTriangles) subdivide(sculpt.positions, sculpt.indices);
    if (progress) progress(0.2f);

    // Project in blocks so the progress callback (called from this thread
    // only) can report.
    const size_t n = sculpt.positions.size();
    const size_t blocks = 8;
    for (size_t b = 0; b < blocks; ++b) {
        size_t first = n * b / blocks, last = n * (b + 1) / blocks;
        core::parallelForRanges(uint32_t(last - first), 256, 0, [&](core::IndexRange range) {
        const size_t begin = range.begin, end = range.end;
            for (size_t i = first + begin; i < first + end; ++i) {
                glm::vec3 normal;
                // The planar cage is within a couple of centimetres of the
                // shape; cap the move so a bad gradient cannot fling a vertex.
                glm::vec3 p = sdf.project(sculpt.positions[i], 2, 0.04f, &normal);
                sculpt.positions[i] = p + normal * skin.sample(p).displacement;
            }
        });
        if (progress) progress(0.2f + 0.8f * static_cast<float>(b + 1) / static_cast<float>(blocks));
    }
    return sculpt;
}

} // namespace tessera::creature
