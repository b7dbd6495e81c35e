#include "tessera/terrain/TessLevels.h"

#include "tessera/scene/Camera.h"
#include "tessera/terrain/Terrain.h"

#include "tessera/shaders/TerrainPatches.h"
#include "tessera/shaders/TessFactors.h"

#include <algorithm>
#include <cmath>

namespace tessera::terrain {
namespace {

// A point of the control mesh at ground height: grid coordinates to world.
glm::vec3 groundPoint(const Terrain& terrain, glm::vec2 gridPoint) {
    const glm::vec2 xz = gridPoint * terrain.grid().patchSize();
    return {xz.x, terrain.heightAt(xz.x, xz.y), xz.y};
}

float edgeLevel(const Terrain& terrain, const TessellationSettings& s, const TessView& view, uint32_t edge,
                float minLevel, float maxLevel) {
    glm::vec2 along{0.0f};
    const glm::vec2 start = shader::tsEdgeStart(edge, terrain.grid().patchesPerSide(), along);
    const glm::vec3 a = groundPoint(terrain, start), b = groundPoint(terrain, start + along);
    switch (s.metric) {
    case TessMetric::ScreenEdge:
        return shader::tsScreenEdgeLevel(a, b, view.eye, view.pixelsPerMetre, s.targetPixels);
    case TessMetric::Distance:
        return shader::tsDistanceLevel(a, b, view.eye, s.farDistance, minLevel, maxLevel);
    case TessMetric::Silhouette:
        return shader::tsSilhouetteLevel(a, b, terrain.normalAt(a.x, a.z), terrain.normalAt(b.x, b.z), view.eye,
                                         view.pixelsPerMetre, s.targetPixels);
    case TessMetric::HeightDetail:
        return shader::tsDetailLevel(a, b, view.eye, terrain.detail().edgeError()[edge], view.pixelsPerMetre,
                                     s.targetPixels);
    }
    return minLevel;
}

} // namespace

TessView TessView::fromCamera(const scene::Camera& camera, uint32_t viewportHeight) {
    // As BasicTerrainBackend::pixelsPerMetre and the null backend.
    return {camera.position(), float(viewportHeight) * std::abs(camera.projection()[1][1]) * 0.5f};
}

TessLevels computeTessLevels(const Terrain& terrain, const TessellationSettings& settings, const TessView& view,
                             float backendMaxLevel) {
    const PatchGrid& grid = terrain.grid();
    const float maxLevel = std::min(settings.maxLevel, backendMaxLevel);
    // Not std::clamp: it requires lo <= hi, and maxLevel may be below 1.
    const float minLevel = std::min(std::max(settings.minLevel, 1.0f), maxLevel);
    TessLevels levels{std::vector<float>(grid.edgeCount(), 0.0f), std::vector<float>(grid.patchCount(), 0.0f)};

    switch (settings.mode) {
    case TerrainMode::LowRes:
        std::fill(levels.edges.begin(), levels.edges.end(), 1.0f);
        std::fill(levels.patches.begin(), levels.patches.end(), 1.0f);
        break;
    case TerrainMode::Continuous:
        std::fill(levels.edges.begin(), levels.edges.end(),
                  std::min(std::max(settings.continuousLevel, 1.0f), backendMaxLevel));
        break;
    case TerrainMode::Adaptive:
        for (uint32_t e = 0; e < grid.edgeCount(); ++e)
            levels.edges[e] = std::clamp(edgeLevel(terrain, settings, view, e, minLevel, maxLevel), minLevel, maxLevel);
        // The interior term exists only for the detail metric: a patch can be
        // rough inside while all four edges run over smooth ground.
        if (settings.metric == TessMetric::HeightDetail) {
            const uint32_t p = grid.patchesPerSide();
            for (uint32_t patch = 0; patch < grid.patchCount(); ++patch) {
                const glm::vec2 lo(float(patch % p), float(patch / p));
                const glm::vec3 c0 = groundPoint(terrain, lo), c1 = groundPoint(terrain, lo + glm::vec2(1.0f));
                const float level = shader::tsDetailLevel(c0, c1, view.eye, terrain.detail().patchError()[patch],
                                                          view.pixelsPerMetre, settings.targetPixels);
                levels.patches[patch] = std::clamp(level, minLevel, maxLevel);
            }
        }
        break;
    }
    return levels;
}

std::array<float, 2> innerLevels(const TessLevels& levels, const PatchGrid& grid, uint32_t patch) {
    const std::array<uint32_t, 4> e = grid.patchEdges(patch);
    const float interior = levels.patches[patch];
    return {std::max({levels.edges[e[1]], levels.edges[e[3]], interior}),
            std::max({levels.edges[e[0]], levels.edges[e[2]], interior})};
}

} // namespace tessera::terrain
