#pragma once
/// @file CharacterPoser.h
/// Turns placed characters into a frame's draw items: the LOD manager
/// (lod::LodManager) picks each one's tier, level and cross-fade within the
/// frame budget, and only the instances it draws are posed on the CPU (clip
/// sampled, globals, skinning palette). Poses and palettes are kept per
/// drawn slot, so a frame allocates nothing once the slots exist. Both the
/// characters scene and the crowd scene draw through it.

#include "tessera/runtime/CharacterAssets.h"
#include "tessera/backend/CharacterDesc.h"
#include "tessera/character/Pose.h"
#include "tessera/lod/LodManager.h"
#include "tessera/scene/Camera.h"

#include <deque>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace tessera::runtime {

/// How the frame's characters are tessellated and budgeted.
struct CharacterLevels {
    uint32_t viewportHeight = 720;
    /// The backend's highest level.
    float maxLevel = 64.0f;
    std::optional<float> fixedLevel; ///< --character-level (the budget still caps it)
    /// Thresholds and budget: the device class's defaults and the --lod-* flags.
    lod::LodPolicy lod;
};

class CharacterPoser {
public:
    /// Starts a frame seen by `camera`: clears the offers and the items.
    void begin(const scene::Camera& camera, const CharacterLevels& levels);
    /// Offers instance `id` (stable from frame to frame: its LOD state's
    /// key) of asset `asset` placed at `world` (rigid, uniform scale),
    /// playing clip `clip` (-1: rest pose; looping) at `seconds`. Posed by
    /// finish() only if drawn.
    void offer(uint32_t id, uint32_t asset, const glm::mat4& world, int clip, float seconds);
    /// Selects the offered instances' tiers and poses the drawn ones.
    void finish(const CharacterAssets& assets);

    std::span<const backend::CharacterDrawItem> items() const { return mItems; }
    /// The LOD manager's answer for the frame (tiers, counts, parameters).
    const lod::LodFrame& lod() const { return mLod.frame(); }

private:
    struct Offer {
        uint32_t asset = 0;
        glm::mat4 world{1.0f};
        int clip = -1;
        float seconds = 0.0f;
    };
    struct Slot {
        const character::Skeleton* skeleton = nullptr;
        std::unique_ptr<character::Pose> pose;
        std::vector<glm::mat4> palette;
    };

    /// Poses offer `offer` into the next slot and returns its palette.
    std::span<const glm::mat4> pose(const CharacterAssets& assets, const Offer& offer);

    scene::Camera mCamera;
    CharacterLevels mLevels;
    lod::LodManager mLod;
    std::vector<Offer> mOffers;
    std::vector<lod::LodInstance> mInstances;
    std::vector<lod::LodCharacter> mCharacters;
    std::vector<int32_t> mSlotOf; ///< per offer: its slot this frame, -1 when not posed
    size_t mSlotsUsed = 0;
    // A deque: items point into the palettes, which must not move as slots are added.
    std::deque<Slot> mSlots;
    std::vector<backend::CharacterDrawItem> mItems;
};

} // namespace tessera::runtime
