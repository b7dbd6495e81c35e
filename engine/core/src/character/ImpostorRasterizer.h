#pragma once
// ImpostorRasterizer: the visibility samples of one impostor cell (private
// to the baker). Triangles arrive in cell coordinates (tsImpostorProject's
// s, t and depth); each sample keeps the nearest triangle and its
// barycentric weights, and the baker shades only the samples that survive.

#include "tessera/shaders/CrowdImpostor.h"

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace tessera::character {

class ImpostorRasterizer {
public:
    /// Texels a side of a cell's inner square (tsImpostorCellTexel).
    static constexpr uint32_t kInnerTexels = TS_IMPOSTOR_CELL - 2u * TS_IMPOSTOR_BORDER;
    /// Samples a side of one texel (2 x 2 supersampling).
    static constexpr uint32_t kSamplesPerTexel = 2;
    /// Samples a side of the inner square: sample (x, y) sits at
    /// s = (x + 0.5) / kSide, t = (y + 0.5) / kSide.
    static constexpr uint32_t kSide = kInnerTexels * kSamplesPerTexel;
    static constexpr uint32_t kNone = UINT32_MAX;

    struct Sample {
        float depth = 0.0f;
        uint32_t triangle = kNone; ///< kNone: nothing covers it
        float weight1 = 0.0f;      ///< barycentric weight of the triangle's second corner
        float weight2 = 0.0f;      ///< ... and of its third (the first's is 1 - both)
    };

    ImpostorRasterizer() : mSamples(kSide * kSide) {}

    /// Empties every sample.
    void clear();
    /// Draws triangle `triangle` with corners (s, t, depth). A sample is
    /// covered when it lies inside or on the triangle's edges; it keeps the
    /// largest depth (nearest the eye), an equal depth the triangle drawn
    /// first, so the result depends only on the order of the draws.
    /// Degenerate and non-finite triangles draw nothing.
    void draw(uint32_t triangle, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c);

    const Sample& sample(uint32_t x, uint32_t y) const { return mSamples[y * kSide + x]; }

private:
    std::vector<Sample> mSamples;
};

} // namespace tessera::character
