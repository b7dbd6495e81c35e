#include "CharacterPoser.h"

#include <algorithm>
#include <cmath>

namespace tessera::demo {

void CharacterPoser::begin(const scene::Camera& camera, const CharacterLevels& levels) {
    mItems.clear();
    mFrustum = camera.frustum();
    mEye = camera.position();
    mLevels = levels;
    mPixelsPerRadian = float(levels.viewportHeight) / (2.0f * std::tan(0.5f * camera.verticalFov()));
}

bool CharacterPoser::visible(const CrowdAsset& asset, const glm::mat4& world) const {
    return mFrustum.intersects(asset.box.transformed(world));
}

void CharacterPoser::add(const CharacterAssets& assets, uint32_t index, const glm::mat4& world, int clip,
                         float seconds) {
    const CrowdAsset& asset = assets[index];
    const character::CharacterAsset& character = asset.asset;
    if (mItems.size() == mSlots.size()) mSlots.emplace_back();
    Slot& slot = mSlots[mItems.size()];
    // A slot keeps its pose while it draws the same skeleton (every frame in
    // the characters scene; whenever the same creature lands in it in the crowd).
    if (slot.skeleton != &character.skeleton) {
        slot.pose = std::make_unique<character::Pose>(character.skeleton);
        slot.skeleton = &character.skeleton;
    }
    slot.pose->reset();
    if (clip >= 0) slot.pose->apply(character.clips[size_t(clip)], seconds);
    slot.pose->computeGlobals();
    slot.pose->palette(character.cage, slot.palette);

    float level = mLevels.fixedLevel.value_or(0.0f);
    if (!mLevels.fixedLevel) {
        // Edges grow with the world matrix's (uniform) scale.
        const float scale = glm::length(glm::vec3(world[0]));
        const glm::vec3 centre = glm::vec3(world * glm::vec4(asset.box.center(), 1.0f));
        const float distance = std::max(glm::distance(centre, mEye), 0.1f);
        level = asset.meanEdge * scale * mPixelsPerRadian / distance / kTargetEdgePixels;
    }
    backend::CharacterDrawItem item;
    item.character = assets.handle(index);
    item.world = world;
    item.palette = slot.palette;
    item.tessLevel = std::clamp(level, 1.0f, mLevels.maxLevel);
    mItems.push_back(item);
}

} // namespace tessera::demo
