#pragma once
/// @file HorizonPyramid.h
/// The horizon test (shader::tsLodBehindTerrain, CrowdLod.h) on the CPU,
/// with the same answer, faster: a max pyramid over the horizon grid bounds
/// the cells a run of the test's points can read, and a run whose sight
/// lines stay above that bound is skipped without reading its points. At a
/// million agents the plain test was most of the LOD manager's frame (up to
/// 64 points for each of 844,000 agents in view). A group of spheres that
/// lie together (a crowd's agents in memory order) is also proven at once,
/// where it can be: none of them hidden, or all of them hidden at one
/// stretch of their sight lines (GroupSight). See docs/CROWD.md 6.1.

#include "tessera/shaders/CrowdLod.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace tessera::lod {

/// What the tests of a group of spheres are sure to answer, from the
/// group's bounds alone (HorizonPyramid::proveGroup).
struct GroupSight {
    enum class Verdict : uint8_t {
        Unknown,    ///< test each sphere
        NoneHidden, ///< no sphere within the bounds is hidden
        /// Every point of any sphere's sight line at a fraction of the way in
        /// [from, to] is blocked: a sphere with a test point there is hidden.
        Blocked,
    };
    Verdict verdict = Verdict::Unknown;
    float from = 0.0f, to = 0.0f;
};

/// The bounds of a group of spheres: their centres' box and largest radius.
struct SphereBounds {
    glm::vec3 lo{0.0f}, hi{0.0f};
    float radius = 0.0f;
    uint32_t count = 0; ///< spheres added
    /// Grows the bounds to hold `sphere` (xyz centre, w radius).
    void add(const glm::vec4& sphere) {
        const glm::vec3 c(sphere);
        lo = count ? glm::min(lo, c) : c;
        hi = count ? glm::max(hi, c) : c;
        radius = count ? std::max(radius, sphere.w) : sphere.w;
        ++count;
    }
};

class HorizonPyramid {
public:
    /// Builds the pyramids over `occluders` (n x n, row by row; CrowdLodParams::
    /// occluder.w cells a side), copying them; nullptr: no grid.
    void build(const float* occluders, uint32_t n);
    /// Exactly shader::tsLodBehindTerrain(sphere, p, occluders) for the grid
    /// built (`p.occluder.w` must be its side).
    bool behindTerrain(const glm::vec4& sphere, const shader::CrowdLodParams& p) const;
    /// What every sphere with its centre in `bounds.lo..hi` and a radius of
    /// at most `bounds.radius` would get from behindTerrain, where the grid's
    /// bounds alone decide it (with room for the test's float rounding).
    GroupSight proveGroup(const SphereBounds& bounds, const shader::CrowdLodParams& p) const;
    /// behindTerrain(sphere, p) for a sphere within the bounds `group` was
    /// proven for: the same answer, from the proof where it decides.
    bool behindTerrain(const glm::vec4& sphere, const shader::CrowdLodParams& p, const GroupSight& group) const;

private:
    /// Whether some point in [first, last] may be blocked: false only when
    /// every sight line through their cross-sections stays above the highest
    /// cell any of them could read.
    bool runMayBeBlocked(uint32_t first, uint32_t last, uint32_t steps, const glm::vec4& delta,
                         const glm::vec2& cone, const shader::CrowdLodParams& p) const;
    /// The n x n grid followed by its max (`highest`) or min pyramid, level k
    /// = 1, 2, ... the extreme of each 2^k x 2^k block, ceil(n / 2^k) a side,
    /// row by row, up to a level of one: one array, read in place.
    static void appendLevels(const float* grid, uint32_t n, std::vector<float>& out, bool highest);
    /// The highest cell in [i0, i1] x [j0, j1] (clamped to the grid, not empty).
    float highest(int32_t i0, int32_t j0, int32_t i1, int32_t j1) const;
    /// The lowest cell in the same way (the min pyramid).
    float lowest(int32_t i0, int32_t j0, int32_t i1, int32_t j1) const;
    /// Where the sight lines of a group's spheres run over the fraction
    /// [ta, tb] of their way: the grid cells (unclamped) their test points
    /// could read and the lowest and highest of the points' heights.
    struct Stretch {
        int32_t i0, j0, i1, j1;
        double yLow, yHigh, rho;
    };
    Stretch stretch(const SphereBounds& bounds, const shader::CrowdLodParams& p, double ta, double tb) const;
    bool noneBlocked(const SphereBounds& bounds, const shader::CrowdLodParams& p, double ta, double tb,
                     uint32_t depth) const;

    uint32_t mSide = 0; ///< 0: no grid
    /// The grid and its max and min pyramids (appendLevels).
    std::vector<float> mHighest, mLowest;
};

} // namespace tessera::lod
