#pragma once
/// @file MeteorShower.h
/// A deterministic schedule of crater impacts for the demo's flythrough.

#include "tessera/terrain/CraterSplat.h"

#include <cstdint>
#include <functional>
#include <vector>

#include <glm/vec2.hpp>

namespace tessera::terrain {

struct MeteorImpact {
    double timeSeconds = 0.0;
    CraterSplat splat;
};

struct MeteorShowerSettings {
    uint32_t count = 0;
    uint32_t seed = 1;
    double startSeconds = 0.0;    ///< first impact no earlier than this
    double durationSeconds = 2.0; ///< impacts spread over [start, start + duration)
    float minRadius = 35.0f;
    float maxRadius = 110.0f;
    /// Impacts land within this distance of the aim point (metres).
    float scatter = 450.0f;
    glm::vec2 regionMin{0.0f}; ///< impacts are kept inside this world XZ rectangle
    glm::vec2 regionMax{0.0f};
};

/// Impacts sorted by time. `aimAt(t)` gives the world XZ the shower aims at
/// at time t (the demo aims ahead of the camera so the craters appear in
/// view). The same settings always give the same impacts on every platform
/// (the core's `Random`; no std distributions, whose output varies by
/// library). Every crater has scaledCraterProfile's shape for its radius.
std::vector<MeteorImpact> scheduleMeteorShower(const MeteorShowerSettings& settings,
                                               const std::function<glm::vec2(double)>& aimAt);

} // namespace tessera::terrain
