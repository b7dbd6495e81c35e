#include "tessera/runtime/CharacterPoser.h"

#include <algorithm>
#include <cmath>

namespace tessera::runtime {

void CharacterPoser::begin(const scene::Camera& camera, const CharacterLevels& levels) {
    mItems.clear();
    mOffers.clear();
    mInstances.clear();
    mCamera = camera;
    mLevels = levels;
    lod::LodPolicy policy = levels.lod;
    policy.fixedLevel = levels.fixedLevel.value_or(0.0f);
    // Characters drawn one by one have no impostor tier (it is the instanced
    // crowd's, drawn from its lists): the far tier takes the smallest.
    policy.impostorPixels = 0.0f;
    policy.budget.maxFarInstances = lod::LodBudget::kUnlimited;
    mLod.setPolicy(policy);
}

void CharacterPoser::offer(uint32_t id, uint32_t asset, const glm::mat4& world, int clip, float seconds) {
    mOffers.push_back({asset, world, clip, seconds});
    lod::LodInstance instance;
    instance.id = id;
    instance.character = asset;
    mInstances.push_back(instance);
}

std::span<const glm::mat4> CharacterPoser::pose(const CharacterAssets& assets, const Offer& offer) {
    const character::CharacterAsset& character = assets[offer.asset].asset;
    if (mSlotsUsed == mSlots.size()) mSlots.emplace_back();
    Slot& slot = mSlots[mSlotsUsed++];
    // A slot keeps its pose while it draws the same skeleton (every frame in
    // the characters scene; whenever the same creature lands in it in the crowd).
    if (slot.skeleton != &character.skeleton) {
        slot.pose = std::make_unique<character::Pose>(character.skeleton);
        slot.skeleton = &character.skeleton;
    }
    slot.pose->reset();
    if (offer.clip >= 0) slot.pose->apply(character.clips[size_t(offer.clip)], offer.seconds);
    slot.pose->computeGlobals();
    slot.pose->palette(character.cage, slot.palette);
    return slot.palette;
}

void CharacterPoser::finish(const CharacterAssets& assets) {
    // What each tier costs per asset, and every instance's bounding sphere:
    // the compression box holds every pose the clips reach.
    mCharacters.resize(assets.size());
    for (size_t a = 0; a < assets.size(); ++a) {
        const CrowdAsset& asset = assets[a];
        const float radius = std::max(glm::length(asset.box.extents()), 1e-6f);
        lod::LodCharacter& c = mCharacters[a];
        c.levelPerPixel = lod::LodCharacter::levelPerPixelFor(asset.meanEdge, radius, mLevels.lod.targetEdgePixels);
        c.cageTriangles = asset.asset.cage.triangleCount();
        c.middleTriangles = c.cageTriangles;
        c.farTriangles = c.cageTriangles; // the far mesh arrives with instanced crowd draws
    }
    for (size_t i = 0; i < mOffers.size(); ++i) {
        const Offer& offer = mOffers[i];
        const scene::Aabb& box = assets[offer.asset].box;
        const float scale = glm::length(glm::vec3(offer.world[0]));
        const glm::vec3 centre = glm::vec3(offer.world * glm::vec4(box.center(), 1.0f));
        mInstances[i].sphere = glm::vec4(centre, glm::length(box.extents()) * scale);
    }
    const lod::LodFrame& frame =
        mLod.update(mInstances, mCharacters, lod::LodView::fromCamera(mCamera, mLevels.viewportHeight, mLevels.maxLevel));

    mSlotsUsed = 0;
    mSlotOf.assign(mOffers.size(), -1);
    for (uint32_t tier = 0; tier < lod::kTierCount; ++tier)
        for (const lod::LodDraw& draw : frame.tiers[tier]) {
            int32_t& slot = mSlotOf[draw.instance];
            if (slot < 0) {
                slot = int32_t(mSlotsUsed);
                pose(assets, mOffers[draw.instance]);
            }
            const Offer& offer = mOffers[draw.instance];
            backend::CharacterDrawItem item;
            item.character = assets.handle(offer.asset);
            item.world = offer.world;
            item.palette = mSlots[size_t(slot)].palette;
            item.tessLevel = draw.level;
            item.tier = tier;
            item.coverage = draw.coverage;
            item.fadingOut = draw.fadingOut;
            mItems.push_back(item);
        }
}

} // namespace tessera::runtime
