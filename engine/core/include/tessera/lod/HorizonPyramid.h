#pragma once
/// @file HorizonPyramid.h
/// The horizon test (shader::tsLodBehindTerrain, CrowdLod.h) on the CPU,
/// with the same answer, faster: a max pyramid over the horizon grid bounds
/// the cells a run of the test's points can read, and a run whose sight
/// lines stay above that bound is skipped without reading its points. At a
/// million agents the plain test was most of the LOD manager's frame (up to
/// 64 points for each of 844,000 agents in view). See docs/CROWD.md 6.1.

#include "tessera/shaders/CrowdLod.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace tessera::lod {

class HorizonPyramid {
public:
    /// Builds the pyramid over `occluders` (n x n, row by row; CrowdLodParams::
    /// occluder.w cells a side). `occluders` must outlive the tests.
    void build(const float* occluders, uint32_t n);
    /// Exactly shader::tsLodBehindTerrain(sphere, p, occluders) for the grid
    /// built (`p.occluder.w` must be its side).
    bool behindTerrain(const glm::vec4& sphere, const shader::CrowdLodParams& p) const;

private:
    /// Whether some point in [first, last] may be blocked: false only when
    /// every sight line through their cross-sections stays above the highest
    /// cell any of them could read.
    bool runMayBeBlocked(uint32_t first, uint32_t last, uint32_t steps, const glm::vec4& delta,
                         const glm::vec2& cone, const shader::CrowdLodParams& p) const;
    /// The highest cell in [i0, i1] x [j0, j1] (clamped to the grid, not empty).
    float highest(int32_t i0, int32_t j0, int32_t i1, int32_t j1) const;

    const float* mGrid = nullptr;
    uint32_t mSide = 0;
    /// Level k >= 1: the max of 2^k x 2^k cells; side ceil(n / 2^k).
    std::vector<std::vector<float>> mLevels;
    std::vector<uint32_t> mSides;
};

} // namespace tessera::lod
