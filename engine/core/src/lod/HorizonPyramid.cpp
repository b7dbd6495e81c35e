#include "tessera/lod/HorizonPyramid.h"

#include <algorithm>
#include <cmath>

namespace tessera::lod {
namespace {

// Points bounded together: a bound costs about two points.
constexpr uint32_t kRun = 8;

} // namespace

void HorizonPyramid::build(const float* occluders, uint32_t n) {
    mGrid = occluders;
    mSide = n;
    mSides.assign(1, n);
    // Rebuilt every frame (craters change the grid); the levels keep their storage.
    size_t levels = 0;
    for (uint32_t side = n; side > 1; side = (side + 1) / 2) ++levels;
    mLevels.resize(levels);
    const float* below = occluders;
    uint32_t side = n;
    for (size_t k = 0; k < levels; ++k) {
        const uint32_t up = (side + 1) / 2;
        std::vector<float>& level = mLevels[k];
        level.resize(size_t(up) * up);
        for (uint32_t j = 0; j < up; ++j)
            for (uint32_t i = 0; i < up; ++i) {
                const uint32_t i1 = std::min(2 * i + 1, side - 1), j1 = std::min(2 * j + 1, side - 1);
                level[size_t(j) * up + i] =
                    std::max(std::max(below[size_t(2 * j) * side + 2 * i], below[size_t(2 * j) * side + i1]),
                             std::max(below[size_t(j1) * side + 2 * i], below[size_t(j1) * side + i1]));
            }
        mSides.push_back(up);
        below = level.data();
        side = up;
    }
}

float HorizonPyramid::highest(int32_t i0, int32_t j0, int32_t i1, int32_t j1) const {
    // The finest level where the rectangle spans at most two blocks a side.
    uint32_t k = 0;
    while ((i1 >> k) - (i0 >> k) > 1 || (j1 >> k) - (j0 >> k) > 1) ++k;
    k = std::min<uint32_t>(k, uint32_t(mSides.size()) - 1);
    const float* cells = k == 0 ? mGrid : mLevels[k - 1].data();
    const int32_t side = int32_t(mSides[k]);
    const int32_t a = std::min(i0 >> k, side - 1), b = std::min(i1 >> k, side - 1);
    const int32_t c = std::min(j0 >> k, side - 1), e = std::min(j1 >> k, side - 1);
    return std::max(std::max(cells[c * side + a], cells[c * side + b]),
                    std::max(cells[e * side + a], cells[e * side + b]));
}

bool HorizonPyramid::runMayBeBlocked(uint32_t first, uint32_t last, uint32_t steps, const glm::vec4& delta,
                                     const glm::vec2& cone, const shader::CrowdLodParams& p) const {
    // The points' x, z, y and rho, computed as the shader computes them, are
    // each monotonic in the point's index (every float operation on them is
    // monotonic), so the run's two ends bound them all: each point's cells
    // lie within [min x - max rho, max x + max rho] (and z alike), and its y
    // is at least the lower end's. A point is blocked only where y + rho +
    // margin is below one of its cells; rho >= 0, so when the lower end's
    // y + margin reaches the highest cell the run could read, none is.
    const glm::vec4 q0 = shader::tsLodSightPoint(first, steps, delta, cone, p);
    const glm::vec4 q1 = shader::tsLodSightPoint(last, steps, delta, cone, p);
    const float cell = p.occluder.z;
    const float rho = std::max(q0.w, q1.w);
    const float i0 = std::floor((std::min(q0.x, q1.x) - rho) / cell), i1 = std::floor((std::max(q0.x, q1.x) + rho) / cell);
    const float j0 = std::floor((std::min(q0.z, q1.z) - rho) / cell), j1 = std::floor((std::max(q0.z, q1.z) + rho) / cell);
    const float n = float(mSide);
    // A point reads cells only with all four inside the grid.
    if (i1 < 0.0f || j1 < 0.0f || i0 >= n || j0 >= n) return false;
    const auto clampCell = [n](float v) { return int32_t(std::clamp(v, 0.0f, n - 1.0f)); };
    const float bound = highest(clampCell(i0), clampCell(j0), clampCell(i1), clampCell(j1));
    return std::min(q0.y, q1.y) + TS_LOD_OCCLUSION_MARGIN < bound;
}

bool HorizonPyramid::behindTerrain(const glm::vec4& sphere, const shader::CrowdLodParams& p) const {
    if (uint32_t(p.occluder.w) == 0u || mGrid == nullptr) return false;
    glm::vec4 delta;
    glm::vec2 cone;
    const uint32_t steps = shader::tsLodSight(sphere, p, delta, cone);
    // The first run point by point (a low eye's sight is mostly blocked near
    // it, where a bound would fail), then one bound per run.
    for (uint32_t first = 1; first <= steps; first += kRun) {
        const uint32_t last = std::min(first + kRun - 1, steps);
        if (first > 1 && !runMayBeBlocked(first, last, steps, delta, cone, p)) continue;
        for (uint32_t s = first; s <= last; ++s)
            if (shader::tsLodSightBlockedAt(s, steps, delta, cone, p, mGrid)) return true;
    }
    return false;
}

} // namespace tessera::lod
