#pragma once
/// @file ShadowCasters.h
/// The square of ground the characters' shadows are drawn over, and the
/// casters in it: what SceneRun hands the backend each frame
/// (FrameInfo::shadowCasters, shadowRegion).

#include "tessera/scene/Camera.h"

#include <glm/glm.hpp>
#include <vector>

namespace tessera::runtime {

/// Side of the shadowed square (metres): 1024 mask texels of 9 cm, enough for
/// a goblin-sized character's shadow to keep its shape close up; further
/// away the characters are too small on screen for theirs to show.
inline constexpr float kShadowRegionSide = 96.0f;
/// Casters drawn at most (CharacterShadowPass::kMaxCasters).
inline constexpr uint32_t kMaxShadowCasters = 8192;

/// The square ahead of `camera` (x, y: min corner in world XZ, z: side), so
/// that most of it is in view: the camera stands a tenth of the way in.
glm::vec3 shadowRegionFor(const scene::Camera& camera);

inline bool insideRegion(const glm::vec3& region, const glm::vec3& p) {
    return p.x >= region.x && p.z >= region.y && p.x < region.x + region.z && p.z < region.y + region.z;
}

/// Keeps the `limit` casters nearest the region's centre.
void keepNearest(const glm::vec3& region, uint32_t limit, std::vector<glm::vec4>& casters);

} // namespace tessera::runtime
