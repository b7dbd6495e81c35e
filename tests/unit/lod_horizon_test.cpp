// Horizon occlusion (tsLodBehindTerrain, CrowdLod.h): an instance is hidden
// only where every sight line to its sphere passes below some cell's lowest
// drawn height first, so culling it never removes a visible pixel.
#include "tessera/lod/HorizonPyramid.h"
#include "tessera/lod/LodManager.h"
#include "tessera/shaders/CrowdLod.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <limits>
#include <random>
#include <string>
#include <vector>

using namespace tessera;

namespace {

constexpr uint32_t kCells = 16;
constexpr float kCell = 10.0f;

struct Grid {
    std::vector<float> lowest = std::vector<float>(kCells * kCells, 0.0f);
    float& at(uint32_t i, uint32_t j) { return lowest[j * kCells + i]; }
    float lowestAt(float x, float z) const {
        const int i = int(std::floor(x / kCell)), j = int(std::floor(z / kCell));
        if (i < 0 || j < 0 || i >= int(kCells) || j >= int(kCells)) return -1e30f;
        return lowest[size_t(j) * kCells + size_t(i)];
    }
};

shader::CrowdLodParams params(const glm::vec3& eye) {
    shader::CrowdLodParams p{};
    p.eye = glm::vec4(eye, 500.0f);
    p.occluder = glm::vec4(0.0f, 0.0f, kCell, float(kCells));
    return p;
}

bool hidden(const Grid& grid, const glm::vec3& eye, const glm::vec4& sphere) {
    return shader::tsLodBehindTerrain(sphere, params(eye), grid.lowest.data());
}

/// Whether the sight line from `eye` to `target` passes below a cell's
/// lowest height somewhere (then it meets the drawn terrain first).
bool lineBlocked(const Grid& grid, const glm::vec3& eye, const glm::vec3& target) {
    for (int k = 1; k < 2000; ++k) {
        const glm::vec3 q = eye + (target - eye) * (float(k) / 2000.0f);
        if (q.y < grid.lowestAt(q.x, q.z)) return true;
    }
    return false;
}

/// An n x n grid of lowest heights: smooth hills with sharp ridges now and
/// then, and with `deepCells` some cells far below.
std::vector<float> hills(uint32_t n, int grid, std::mt19937& random, bool deepCells) {
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::vector<float> lowest(size_t(n) * n);
    for (uint32_t j = 0; j < n; ++j)
        for (uint32_t i = 0; i < n; ++i) {
            float h = 20.0f * std::sin(0.3f * float(i) + float(grid)) * std::cos(0.2f * float(j)) +
                      (unit(random) < 0.05f ? 40.0f * unit(random) : 0.0f);
            if (deepCells && unit(random) < 0.02f) h -= 100.0f;
            lowest[size_t(j) * n + i] = h;
        }
    return lowest;
}

/// Parameters for such a grid of `cell`-metre cells, its origin off zero.
shader::CrowdLodParams gridParams(uint32_t n, float cell) {
    const float side = cell * float(n);
    shader::CrowdLodParams p{};
    p.occluder = glm::vec4(-0.1f * side, -0.2f * side, cell, float(n));
    return p;
}

/// Runs `visit(pyramid, lowest, params, side, where)` on `grids` random
/// grids of each side in `sizes` (cells 2 to 2 + `cellSpread` metres, hills
/// as `hills` makes them), from 8 random eyes each, all from `random`.
template <class Visit>
void forEachView(std::mt19937& random, std::initializer_list<uint32_t> sizes, int grids, float cellSpread,
                 bool deepCells, Visit visit) {
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (const uint32_t n : sizes)
        for (int grid = 0; grid < grids; ++grid) {
            const float cell = 2.0f + cellSpread * unit(random);
            const float side = cell * float(n);
            const std::vector<float> lowest = hills(n, grid, random, deepCells);
            lod::HorizonPyramid pyramid;
            pyramid.build(lowest.data(), n);
            shader::CrowdLodParams p = gridParams(n, cell);
            for (int view = 0; view < 8; ++view) {
                p.eye = glm::vec4(side * (1.4f * unit(random) - 0.3f), 60.0f * unit(random) - 10.0f,
                                  side * (1.4f * unit(random) - 0.3f), 800.0f);
                visit(pyramid, lowest, p, side,
                      "n " + std::to_string(n) + " grid " + std::to_string(grid) + " view " + std::to_string(view));
                if (::testing::Test::HasFatalFailure()) return;
            }
        }
}

/// A ridge along x, 60 to 70 m in z, seen from beyond it by a camera that
/// looks down -z (its default) from (80, 3, 150).
struct RidgeView {
    Grid grid;
    lod::LodView view;
    RidgeView() {
        for (uint32_t i = 0; i < kCells; ++i) grid.at(i, 6) = 20.0f;
        scene::Camera camera;
        camera.setPosition({80.0f, 3.0f, 150.0f});
        view = lod::LodView::fromCamera(camera, 720, 64.0f);
        view.occluders = grid.lowest;
        view.occluderGrid = glm::vec4(0.0f, 0.0f, kCell, float(kCells));
    }
    RidgeView(const RidgeView&) = delete; // the view points into the grid
};

} // namespace

TEST(LodHorizon, FlatGroundHidesNothing) {
    Grid grid;
    const glm::vec3 eye(5.0f, 1.7f, 5.0f);
    for (float x = 20.0f; x < 160.0f; x += 13.0f)
        EXPECT_FALSE(hidden(grid, eye, glm::vec4(x, 0.8f, 150.0f, 0.8f))) << x;
}

TEST(LodHorizon, ARidgeHidesWhatStandsLowBehindItAndNotWhatRisesAbove) {
    Grid grid;
    for (uint32_t i = 0; i < kCells; ++i) grid.at(i, 6) = 20.0f; // a ridge along x, 60 to 70 m in z
    const glm::vec3 eye(80.0f, 3.0f, 15.0f);
    EXPECT_TRUE(hidden(grid, eye, glm::vec4(80.0f, 1.0f, 120.0f, 0.8f)));
    EXPECT_TRUE(hidden(grid, eye, glm::vec4(40.0f, 1.0f, 140.0f, 0.8f)));
    // Above the sight line over the ridge, and in front of it.
    EXPECT_FALSE(hidden(grid, eye, glm::vec4(80.0f, 60.0f, 120.0f, 0.8f)));
    EXPECT_FALSE(hidden(grid, eye, glm::vec4(80.0f, 1.0f, 50.0f, 0.8f)));
    // Without a grid nothing is hidden.
    shader::CrowdLodParams none = params(eye);
    none.occluder.w = 0.0f;
    EXPECT_FALSE(shader::tsLodBehindTerrain(glm::vec4(80.0f, 1.0f, 120.0f, 0.8f), none, grid.lowest.data()));
}

// Random hills, eyes above the ground and spheres anywhere: whenever the test
// hides a sphere, every sight line to points across it passes below a
// cell's lowest height on the way (never a visible pixel culled); and it
// does hide some.
TEST(LodHorizon, HidesOnlyWhatEverySightLineLosesBehindTheTerrain) {
    std::mt19937 random(7);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    uint32_t hiddenCount = 0;
    for (int trial = 0; trial < 300; ++trial) {
        Grid grid;
        for (float& h : grid.lowest) h = 25.0f * unit(random) * unit(random);
        const glm::vec3 eye(kCell * kCells * unit(random), 0.0f, kCell * kCells * unit(random));
        const glm::vec3 at(kCell * kCells * unit(random), 0.0f, kCell * kCells * unit(random));
        const glm::vec3 eyeAbove(eye.x, std::max(grid.lowestAt(eye.x, eye.z), 0.0f) + 0.5f + 5.0f * unit(random),
                                 eye.z);
        const float radius = 0.3f + 2.0f * unit(random);
        const glm::vec4 sphere(at.x, std::max(grid.lowestAt(at.x, at.z), 0.0f) + radius + 3.0f * unit(random),
                               at.z, radius);
        if (!hidden(grid, eyeAbove, sphere)) continue;
        ++hiddenCount;
        const glm::vec3 c(sphere);
        for (int a = 0; a < 8; ++a)
            for (int b = 0; b < 5; ++b) {
                const float phi = 6.2831853f * float(a) / 8.0f, theta = 3.1415927f * float(b) / 4.0f;
                const glm::vec3 onSphere =
                    c + radius * glm::vec3(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
                EXPECT_TRUE(lineBlocked(grid, eyeAbove, onSphere)) << "trial " << trial;
            }
    }
    std::cout << "[lod horizon] " << hiddenCount << " of 300 random spheres hidden\n";
    EXPECT_GT(hiddenCount, 20u);
}

// The LOD manager's pyramid skips runs of points that cannot be blocked: it
// must give the shared rule's answer for every sphere, on grids of any side
// (odd ones too), with eyes high and low, near and far.
TEST(LodHorizon, ThePyramidGivesTheSharedRulesAnswer) {
    std::mt19937 random(23);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    uint32_t hiddenCount = 0, visibleCount = 0;
    forEachView(random, {1u, 2u, 7u, 16u, 37u, 128u}, 12, 30.0f, true,
                [&](const lod::HorizonPyramid& pyramid, const std::vector<float>& lowest,
                    const shader::CrowdLodParams& p, float side, const std::string& where) {
                    for (int k = 0; k < 400; ++k) {
                        const glm::vec4 sphere(side * (1.4f * unit(random) - 0.3f), 50.0f * unit(random) - 25.0f,
                                               side * (1.4f * unit(random) - 0.3f), 0.2f + 3.0f * unit(random));
                        const bool expected = shader::tsLodBehindTerrain(sphere, p, lowest.data());
                        ASSERT_EQ(pyramid.behindTerrain(sphere, p), expected) << where << " sphere " << k;
                        (expected ? hiddenCount : visibleCount)++;
                    }
                });
    std::cout << "[lod horizon] pyramid: " << hiddenCount << " hidden, " << visibleCount << " not\n";
    EXPECT_GT(hiddenCount, 2000u);
    EXPECT_GT(visibleCount, 2000u);
}

TEST(LodHorizon, TheManagerLeavesHiddenInstancesOutOfEveryTier) {
    const RidgeView ridge;
    const std::vector<lod::LodInstance> instances = {{glm::vec4(80.0f, 1.0f, 120.0f, 0.8f), 0, 0},
                                                     {glm::vec4(80.0f, 1.0f, 30.0f, 0.8f), 1, 0}};
    const std::vector<lod::LodCharacter> characters(1);
    lod::LodManager manager;
    const lod::LodFrame& frame = manager.update(instances, characters, ridge.view);
    EXPECT_NE(shader::tsLodStateTier(manager.state(0)), TS_LOD_NONE);
    EXPECT_EQ(shader::tsLodStateTier(manager.state(1)), TS_LOD_NONE);
    EXPECT_EQ(frame.inView, 1u);
}

// A group of spheres that lie together is proven at once where the grid's
// bounds decide (none hidden, or all blocked at one stretch of their sight
// lines): each sphere must still get the shared rule's answer, and the
// proofs must decide most groups on ground like a crowd's.
TEST(LodHorizon, AGroupProofGivesEachSphereTheSharedRulesAnswer) {
    std::mt19937 random(41);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    uint32_t groups = 0, noneHidden = 0, blocked = 0, hiddenCount = 0, visibleCount = 0;
    forEachView(random, {1u, 7u, 16u, 128u}, 10, 60.0f, false,
                [&](const lod::HorizonPyramid& pyramid, const std::vector<float>& lowest,
                    const shader::CrowdLodParams& p, float side, const std::string& where) {
                    const float cell = p.occluder.z;
                    for (int g = 0; g < 60; ++g) {
                        // 32 spheres within a few metres to a cell of each other.
                        const float spread = (unit(random) < 0.5f ? 4.0f : cell) * unit(random);
                        const glm::vec3 centre(side * (1.4f * unit(random) - 0.3f), 50.0f * unit(random) - 25.0f,
                                               side * (1.4f * unit(random) - 0.3f));
                        std::vector<glm::vec4> spheres;
                        lod::SphereBounds bounds;
                        for (int k = 0; k < 32; ++k) {
                            spheres.emplace_back(centre + spread * glm::vec3(unit(random) - 0.5f, 0.2f * unit(random),
                                                                              unit(random) - 0.5f),
                                                 0.2f + 2.0f * unit(random));
                            bounds.add(spheres.back());
                        }
                        const lod::GroupSight proof = pyramid.proveGroup(bounds, p);
                        ++groups;
                        noneHidden += proof.verdict == lod::GroupSight::Verdict::NoneHidden;
                        blocked += proof.verdict == lod::GroupSight::Verdict::Blocked;
                        for (size_t k = 0; k < spheres.size(); ++k) {
                            const bool expected = shader::tsLodBehindTerrain(spheres[k], p, lowest.data());
                            ASSERT_EQ(pyramid.behindTerrain(spheres[k], p, proof), expected)
                                << where << " group " << g << " sphere " << k << " verdict " << int(proof.verdict);
                            (expected ? hiddenCount : visibleCount)++;
                        }
                    }
                });
    std::cout << "[lod horizon] groups: " << groups << ", proven none hidden " << noneHidden << ", blocked " << blocked
              << "; spheres " << hiddenCount << " hidden, " << visibleCount << " not\n";
    EXPECT_GT(noneHidden, groups / 4);
    EXPECT_GT(blocked, groups / 20);
    EXPECT_GT(hiddenCount, 2000u);
    EXPECT_GT(visibleCount, 2000u);
}

// Spheres that are not finite (a game's bug, never the crowd's) are out of
// view, as every backend leaves them out, and do not spoil the horizon
// proof of the group they fall in.
TEST(LodHorizon, ASphereThatIsNotFiniteIsOutOfViewAndSpoilsNoGroup) {
    const RidgeView ridge;
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    std::vector<lod::LodInstance> instances;
    for (uint32_t k = 0; k < 40; ++k) // in front of the ridge: seen
        instances.push_back({glm::vec4(78.0f + 0.1f * float(k), 1.0f, 100.0f, 0.8f), k, 0});
    instances[3].sphere.x = nan;
    instances[7].sphere.w = inf;
    instances[11].sphere.w = -1.0f;
    const std::vector<lod::LodCharacter> characters(1);
    lod::LodManager manager;
    const lod::LodFrame& frame = manager.update(instances, characters, ridge.view);
    EXPECT_EQ(frame.inView, 37u);
    for (uint32_t k : {3u, 7u, 11u}) EXPECT_EQ(shader::tsLodStateTier(manager.state(k)), TS_LOD_NONE) << k;
    EXPECT_NE(shader::tsLodStateTier(manager.state(0)), TS_LOD_NONE);
}
