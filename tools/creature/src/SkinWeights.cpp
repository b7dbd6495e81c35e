#include "SkinWeights.h"

#include "tessera/core/ParallelFor.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace tessera::creature {

namespace {

// Width of the blend between neighbouring bones (metres).
constexpr float kFalloff = 0.025f;

VertexWeights weigh(const CreatureSdf& sdf, const glm::vec3& p) {
    std::array<float, kJointCount> dist{};
    sdf.boneDistances(p, dist.data());
    float nearest = *std::min_element(dist.begin(), dist.end());
    std::array<std::pair<float, uint32_t>, kJointCount> w{};
    for (uint32_t j = 0; j < kJointCount; ++j) {
        float x = (dist[j] - nearest) / kFalloff;
        // A smooth bump: 1 at the nearest bone, exactly 0 beyond 3 widths.
        float s = std::max(0.0f, 1.0f - x / 3.0f);
        w[j] = {s * s * s, j};
    }
    // Highest weight first; equal weights by joint index, for determinism.
    std::sort(w.begin(), w.end(), [](const auto& a, const auto& b) {
        return a.first != b.first ? a.first > b.first : a.second < b.second;
    });
    VertexWeights out;
    float sum = w[0].first + w[1].first + w[2].first + w[3].first;
    for (int k = 0; k < 4; ++k) {
        if (w[k].first <= 0.0f) continue;
        out.joints[k] = static_cast<uint16_t>(w[k].second);
        out.weights[k] = w[k].first / sum;
    }
    // Make the sum exactly 1 in float despite rounding.
    out.weights[0] = 1.0f - (out.weights[1] + out.weights[2] + out.weights[3]);
    return out;
}

} // namespace

std::vector<VertexWeights> computeSkinWeights(const CreatureSdf& sdf, const std::vector<glm::vec3>& positions) {
    std::vector<VertexWeights> result(positions.size());
    core::parallelForRanges(uint32_t(positions.size()), 256, 0, [&](core::IndexRange range) {
        const size_t begin = range.begin, end = range.end;
        for (size_t i = begin; i < end; ++i) result[i] = weigh(sdf, positions[i]);
    });
    return result;
}

} // namespace tessera::creature
