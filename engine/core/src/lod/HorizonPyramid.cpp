#include "tessera/lod/HorizonPyramid.h"

#include <algorithm>
#include <cmath>

namespace tessera::lod {
namespace {

// Points bounded together: a bound costs about two points.
constexpr uint32_t kRun = 8;
// Room for the float rounding of the shared test's points (metres; its
// coordinates are at most a few kilometres, where a float's step is a
// millimetre), which a group's bounds, worked out in double, do not share.
constexpr double kSlack = 0.05;
// The fraction of the way a point is set at, give or take its rounding.
constexpr double kSlackT = 1e-4;
// A test point's cross-section (tsLodSight) has half side t d r / sqrt(d^2 -
// r^2) <= t r / sqrt(1 - 1/4) for the spheres that get points at all (d >
// 2 r + cell).
constexpr double kSpread = 1.1548;
// Halvings of a group's sight lines before the proof gives up (32 stretches).
constexpr uint32_t kMaxDepth = 5;

} // namespace

void HorizonPyramid::appendLevels(const float* grid, uint32_t n, std::vector<float>& out, bool highest) {
    // The grid, then each level of the 2 x 2 blocks' extreme below it, up
    // to a level of one, in one array (a level's blocks read in place).
    out.assign(grid, grid + size_t(n) * n);
    size_t below = 0;
    for (uint32_t side = n; side > 1; side = (side + 1) / 2) {
        const uint32_t up = (side + 1) / 2;
        const size_t at = out.size();
        out.resize(at + size_t(up) * up);
        for (uint32_t j = 0; j < up; ++j)
            for (uint32_t i = 0; i < up; ++i) {
                const uint32_t i1 = std::min(2 * i + 1, side - 1), j1 = std::min(2 * j + 1, side - 1);
                const float a = out[below + size_t(2 * j) * side + 2 * i], b = out[below + size_t(2 * j) * side + i1];
                const float c = out[below + size_t(j1) * side + 2 * i], d = out[below + size_t(j1) * side + i1];
                out[at + size_t(j) * up + i] =
                    highest ? std::max(std::max(a, b), std::max(c, d)) : std::min(std::min(a, b), std::min(c, d));
            }
        below = at;
    }
}

void HorizonPyramid::build(const float* occluders, uint32_t n) {
    // Rebuilt every frame (craters change the grid); the arrays keep their storage.
    mSide = occluders ? n : 0;
    if (!occluders) return;
    appendLevels(occluders, n, mHighest, true);
    appendLevels(occluders, n, mLowest, false);
}

namespace {

// The extreme of the cells in [i0, i1] x [j0, j1] (inside the grid) from a
// pyramid in appendLevels' layout: the finest level where the rectangle spans
// at most two blocks a side.
template <class Pick>
float pickCells(const std::vector<float>& pyramid, uint32_t n, int32_t i0, int32_t j0, int32_t i1, int32_t j1,
                Pick pick) {
    uint32_t offset = 0, side = n;
    int32_t k = 0;
    while (side > 1 && ((i1 >> k) - (i0 >> k) > 1 || (j1 >> k) - (j0 >> k) > 1)) {
        offset += side * side;
        side = (side + 1) / 2;
        ++k;
    }
    const int32_t last = int32_t(side) - 1;
    const uint32_t a = uint32_t(std::min(i0 >> k, last)), b = uint32_t(std::min(i1 >> k, last));
    const uint32_t c = uint32_t(std::min(j0 >> k, last)), e = uint32_t(std::min(j1 >> k, last));
    const float* cells = pyramid.data() + offset;
    return pick(pick(cells[c * side + a], cells[c * side + b]), pick(cells[e * side + a], cells[e * side + b]));
}

} // namespace

float HorizonPyramid::highest(int32_t i0, int32_t j0, int32_t i1, int32_t j1) const {
    return pickCells(mHighest, mSide, i0, j0, i1, j1, [](float a, float b) { return std::max(a, b); });
}

float HorizonPyramid::lowest(int32_t i0, int32_t j0, int32_t i1, int32_t j1) const {
    return pickCells(mLowest, mSide, i0, j0, i1, j1, [](float a, float b) { return std::min(a, b); });
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
    if (uint32_t(p.occluder.w) == 0u || mSide == 0) return false;
    glm::vec4 delta;
    glm::vec2 cone;
    const uint32_t steps = shader::tsLodSight(sphere, p, delta, cone);
    // The first run point by point (a low eye's sight is mostly blocked near
    // it, where a bound would fail), then one bound per run.
    for (uint32_t first = 1; first <= steps; first += kRun) {
        const uint32_t last = std::min(first + kRun - 1, steps);
        if (first > 1 && !runMayBeBlocked(first, last, steps, delta, cone, p)) continue;
        for (uint32_t s = first; s <= last; ++s)
            if (shader::tsLodSightBlockedAt(s, steps, delta, cone, p, mHighest.data())) return true;
    }
    return false;
}

HorizonPyramid::Stretch HorizonPyramid::stretch(const SphereBounds& bounds, const shader::CrowdLodParams& p,
                                                double ta, double tb) const {
    // A point at fraction t towards a centre c is eye + t (c - eye): bilinear
    // in t and c, so its extremes over the stretch and the box are at their
    // corners.
    const double cell = p.occluder.z;
    auto range = [&](double eye, double lo, double hi, double origin, double& low, double& high) {
        low = high = eye + ta * (lo - eye) - origin;
        for (double t : {ta, tb})
            for (double c : {lo, hi}) {
                const double v = eye + t * (c - eye) - origin;
                low = std::min(low, v);
                high = std::max(high, v);
            }
    };
    double x0, x1, z0, z1, y0, y1;
    range(p.eye.x, bounds.lo.x, bounds.hi.x, p.occluder.x, x0, x1);
    range(p.eye.z, bounds.lo.z, bounds.hi.z, p.occluder.y, z0, z1);
    range(p.eye.y, bounds.lo.y, bounds.hi.y, 0.0, y0, y1);
    Stretch s;
    s.rho = tb * kSpread * double(bounds.radius) + kSlack;
    // Cells as floor() gives them, far enough out that int32 holds them.
    auto index = [cell](double v) { return int32_t(std::clamp(std::floor(v / cell), -1e6, 1e6)); };
    s.i0 = index(x0 - s.rho);
    s.i1 = index(x1 + s.rho);
    s.j0 = index(z0 - s.rho);
    s.j1 = index(z1 + s.rho);
    s.yLow = y0 - kSlack;
    s.yHigh = y1 + kSlack;
    return s;
}

bool HorizonPyramid::noneBlocked(const SphereBounds& bounds, const shader::CrowdLodParams& p, double ta, double tb,
                                 uint32_t depth) const {
    const Stretch s = stretch(bounds, p, ta, tb);
    const int32_t n = int32_t(mSide);
    // A point reads cells only with all four inside the grid.
    if (s.i1 < 0 || s.j1 < 0 || s.i0 >= n || s.j0 >= n) return true;
    const auto clampCell = [n](int32_t v) { return std::clamp(v, 0, n - 1); };
    // A point is blocked only below one of its cells (rho >= 0).
    const double bound = highest(clampCell(s.i0), clampCell(s.j0), clampCell(s.i1), clampCell(s.j1));
    if (s.yLow + TS_LOD_OCCLUSION_MARGIN >= bound) return true;
    if (depth == kMaxDepth) return false;
    const double mid = 0.5 * (ta + tb);
    return noneBlocked(bounds, p, ta, mid, depth + 1) && noneBlocked(bounds, p, mid, tb, depth + 1);
}

GroupSight HorizonPyramid::proveGroup(const SphereBounds& bounds, const shader::CrowdLodParams& p) const {
    GroupSight sight;
    if (uint32_t(p.occluder.w) == 0u || mSide == 0 || noneBlocked(bounds, p, 0.0, 1.0, 0)) {
        sight.verdict = GroupSight::Verdict::NoneHidden;
        return sight;
    }
    // A stretch where every point of every sight line passes below the
    // lowest cell it could read, its cross-section narrower than a cell and
    // all of it over the grid. The longest first: more spheres have a test
    // point within it.
    const int32_t n = int32_t(mSide);
    const double cell = p.occluder.z;
    for (uint32_t stretches = 4; stretches <= (1u << kMaxDepth); stretches *= 2)
        for (uint32_t k = 0; k < stretches; ++k) {
            const double ta = double(k) / stretches, tb = double(k + 1) / stretches;
            const Stretch s = stretch(bounds, p, ta, tb);
            if (s.i0 < 0 || s.j0 < 0 || s.i1 >= n || s.j1 >= n || 2.0 * s.rho >= cell) continue;
            if (s.yHigh + s.rho + TS_LOD_OCCLUSION_MARGIN < lowest(s.i0, s.j0, s.i1, s.j1)) {
                sight.verdict = GroupSight::Verdict::Blocked;
                sight.from = float(ta);
                sight.to = float(tb);
                return sight;
            }
        }
    return sight;
}

bool HorizonPyramid::behindTerrain(const glm::vec4& sphere, const shader::CrowdLodParams& p,
                                   const GroupSight& group) const {
    if (group.verdict == GroupSight::Verdict::NoneHidden) return false;
    if (group.verdict == GroupSight::Verdict::Blocked) {
        glm::vec4 delta;
        glm::vec2 cone;
        const uint32_t steps = shader::tsLodSight(sphere, p, delta, cone);
        if (steps == 0u) return false;
        // The test's points lie at t = reach s / (steps + 1): one inside the
        // stretch is blocked, and so the sphere hidden.
        const double per = double(cone.y) / double(steps + 1u);
        const double first = std::max(1.0, std::ceil((double(group.from) + kSlackT) / per));
        const double last = std::min(double(steps), std::floor((double(group.to) - kSlackT) / per));
        if (first <= last) return true;
    }
    return behindTerrain(sphere, p);
}

} // namespace tessera::lod
