#include "tessera/runtime/CrowdGait.h"

#include "tessera/character/StrideLength.h"

#include <algorithm>

namespace tessera::runtime {
namespace {

float restHeight(const character::CageMesh& cage) {
    float low = 0.0f, high = 0.0f;
    for (size_t i = 0; i < cage.vertices.size(); ++i) {
        const float y = cage.vertices[i].position.y;
        low = i ? std::min(low, y) : y;
        high = i ? std::max(high, y) : y;
    }
    return high - low;
}

} // namespace

void CrowdGait::apply(crowd::CrowdSettings& settings) const {
    settings.walkStrideLength = walkStrideLength;
    settings.strideRadius = strideRadius;
    // The walk clips' pace (their mean): the crowd keeps each clip between
    // minWalkRate and maxWalkRate of it.
    settings.walkCycleSeconds = walkStrideLength / naturalSpeed;
    settings.idleCycleSeconds = idleCycleSeconds;
}

Result<CrowdGait> measureCrowdGait(const CharacterAssets& assets, float height, float strideRadius) {
    if (assets.empty()) return fail("the crowd scene has no creatures to draw");
    CrowdGait gait;
    gait.strideRadius = strideRadius;
    // Height per stride, averaged: the crowd's stride that makes the mean
    // creature `height` tall once each is scaled to walk that stride.
    double heightPerStride = 0.0;
    for (const CrowdAsset& entry : assets.all()) {
        const character::CharacterAsset& asset = entry.asset;
        CreatureGait& creature = gait.creatures.emplace_back();
        creature.walkClip = findClip(asset, "walk");
        creature.idleClip = findClip(asset, "idle");
        creature.height = restHeight(asset.cage);
        if (creature.walkClip >= 0)
            creature.stride = character::measureStride(asset, size_t(creature.walkClip)).strideLength;
        if (creature.stride <= 0.0f || creature.height <= 0.0f)
            return fail(entry.file, ": its walk clip covers no ground (character::measureStride), so the crowd cannot ",
                        "keep its feet from sliding");
        heightPerStride += double(creature.height / creature.stride) / double(assets.size());
    }
    gait.walkStrideLength = float(double(height) / heightPerStride);
    double speed = 0.0;
    for (size_t i = 0; i < gait.creatures.size(); ++i) {
        CreatureGait& creature = gait.creatures[i];
        creature.scale = gait.walkStrideLength / creature.stride;
        const auto& clips = assets[i].asset.clips;
        speed += double(gait.walkStrideLength / clips[size_t(creature.walkClip)].duration()) / double(assets.size());
    }
    gait.naturalSpeed = float(speed);
    const CreatureGait& first = gait.creatures.front();
    if (first.idleClip >= 0 && first.idleClip != first.walkClip)
        gait.idleCycleSeconds = assets[0].asset.clips[size_t(first.idleClip)].duration();
    return gait;
}

} // namespace tessera::runtime
