#pragma once
/// @file TessLevels.h
/// The CPU reference of the GPU tessellation-factor pre-pass: one level per
/// canonical edge and one interior level per patch, for tests and for
/// backends that count or emulate tessellation on the CPU.

#include "tessera/terrain/PatchGrid.h"
#include "tessera/terrain/TessellationSettings.h"

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace tessera::scene {
class Camera;
}

namespace tessera::terrain {

class Terrain;

/// What the metrics need to know about the view.
struct TessView {
    glm::vec3 eye{0.0f};
    /// Viewport height * |projection[1][1]| / 2: pixels covered by one metre
    /// seen face-on from one metre away.
    float pixelsPerMetre = 1.0f;

    /// What the backends' factor passes see of `camera` on a viewport
    /// `viewportHeight` pixels tall (its position and projection).
    static TessView fromCamera(const scene::Camera& camera, uint32_t viewportHeight);
};

/// Levels per canonical edge (PatchGrid numbering) and per patch (patch level:
/// the detail metric's interior term, else 0).
struct TessLevels {
    std::vector<float> edges;
    std::vector<float> patches;
};

/// Computes every edge's and patch's level exactly as the GPU pre-pass does:
///  - maxLevel = min(settings.maxLevel, backendMaxLevel),
///    minLevel = clamp(settings.minLevel, 1, maxLevel);
///  - LowRes: every edge and patch level is 1;
///  - Continuous: every edge is clamp(continuousLevel, 1, backendMaxLevel),
///    patches 0;
///  - Adaptive: each edge's metric (TessFactors.h) on its canonical endpoints
///    at ground height, clamped to [minLevel, maxLevel]; patches 0, except with
///    HeightDetail, where a patch's level is tsDetailLevel over its lowest and
///    highest corners with its patch error, clamped the same way.
/// A shared edge is computed once, so neighbouring patches always agree.
TessLevels computeTessLevels(const Terrain& terrain, const TessellationSettings& settings, const TessView& view,
                             float backendMaxLevel);

/// Inner levels of a patch: inner[0] (along u/X) = max(edge v=0, edge v=1,
/// patch level), inner[1] (along v/Z) = max(edge u=0, edge u=1, patch level).
std::array<float, 2> innerLevels(const TessLevels& levels, const PatchGrid& grid, uint32_t patch);

} // namespace tessera::terrain
