#pragma once
/// @file CharacterPoser.h
/// Turns placed characters into a frame's draw items: poses each on the CPU
/// (clip sampled, globals, skinning palette), picks its tessellation level
/// from its size on screen, and keeps the poses and palettes per drawn slot,
/// so a frame allocates nothing once the slots exist. Both the characters
/// scene and the crowd scene draw through it.

#include "CharacterAssets.h"
#include "tessera/backend/CharacterDesc.h"
#include "tessera/character/Pose.h"
#include "tessera/scene/Camera.h"
#include "tessera/scene/Frustum.h"

#include <deque>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace tessera::demo {

/// How the frame's characters are tessellated: fixed, or from their size on
/// screen, up to the backend's maximum.
struct CharacterLevels {
    uint32_t viewportHeight = 720;
    float maxLevel = 64.0f;
    std::optional<float> fixedLevel; ///< --character-level
};

class CharacterPoser {
public:
    /// A tessellated edge covers about this many pixels on screen when the
    /// level is not fixed.
    static constexpr float kTargetEdgePixels = 1.0f;

    /// Starts a frame seen by `camera`: clears the items.
    void begin(const scene::Camera& camera, const CharacterLevels& levels);
    /// Whether asset `asset` placed at `world` may be in view: its compression
    /// box holds every pose its clips reach, so a character outside can skip
    /// its pose and both passes.
    bool visible(const CrowdAsset& asset, const glm::mat4& world) const;
    /// Poses asset `index` of `assets` at `seconds` of clip `clip` (-1: rest
    /// pose; looping) placed at `world` (rigid, uniform scale), and appends
    /// its draw item.
    void add(const CharacterAssets& assets, uint32_t index, const glm::mat4& world, int clip, float seconds);

    std::span<const backend::CharacterDrawItem> items() const { return mItems; }

private:
    struct Slot {
        const character::Skeleton* skeleton = nullptr;
        std::unique_ptr<character::Pose> pose;
        std::vector<glm::mat4> palette;
    };

    scene::Frustum mFrustum;
    glm::vec3 mEye{0.0f};
    float mPixelsPerRadian = 1.0f;
    CharacterLevels mLevels;
    // A deque: items point into the palettes, which must not move as slots are added.
    std::deque<Slot> mSlots;
    std::vector<backend::CharacterDrawItem> mItems;
};

} // namespace tessera::demo
