#pragma once
// Synthetic terrains and crowd set-ups shared by the crowd tests.

#include "tessera/crowd/Crowd.h"
#include "tessera/terrain/Terrain.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <memory>
#include <vector>

namespace tessera::crowd::test {

/// A terrain of `samples` x `samples` heights `spacing` metres apart, height
/// (metres, 0 to 200) from `height(x, z)`.
inline std::unique_ptr<terrain::Terrain> makeTerrain(uint32_t samples, float spacing,
                                                     const std::function<float(float, float)>& height) {
    constexpr float kRelief = 200.0f;
    std::vector<uint16_t> data(size_t(samples) * samples);
    for (uint32_t j = 0; j < samples; ++j)
        for (uint32_t i = 0; i < samples; ++i) {
            const float h = std::clamp(height(float(i) * spacing, float(j) * spacing), 0.0f, kRelief);
            data[size_t(j) * samples + i] = uint16_t(std::lround(h / kRelief * 65535.0f));
        }
    terrain::HeightField field(samples, samples, std::move(data), terrain::TerrainScale{spacing, kRelief});
    return std::make_unique<terrain::Terrain>(std::move(field), 4);
}

inline std::unique_ptr<terrain::Terrain> flatTerrain(uint32_t samples = 257, float spacing = 1.0f) {
    return makeTerrain(samples, spacing, [](float, float) { return 10.0f; });
}

/// Flat ground with a wall (a 60 m high ridge, two samples wide) along
/// x = wallX, open where `gap(z)` is true.
inline std::unique_ptr<terrain::Terrain> wallTerrain(uint32_t samples, float spacing, float wallX,
                                                     const std::function<bool(float)>& gap) {
    return makeTerrain(samples, spacing, [=](float x, float z) {
        return std::abs(x - wallX) <= spacing && !gap(z) ? 70.0f : 10.0f;
    });
}

/// Settings for the small synthetic worlds: 1 m cells; one thread unless
/// the test says otherwise.
inline CrowdSettings testSettings(uint32_t threads = 0) {
    CrowdSettings s;
    s.cellSize = 1.0f;
    s.threads = threads;
    return s;
}

inline std::unique_ptr<Crowd> makeCrowd(const terrain::Terrain& terrain, const CrowdSettings& settings,
                                        std::vector<GoalGroup> goals, std::vector<SpawnPattern> spawns) {
    auto crowd = Crowd::create(terrain, settings, goals, spawns);
    EXPECT_TRUE(crowd.ok()) << (crowd.ok() ? "" : crowd.error().message);
    return crowd.ok() ? std::move(crowd.value()) : nullptr;
}

inline glm::vec2 xz(const glm::vec3& p) { return {p.x, p.z}; }

} // namespace tessera::crowd::test
