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
    settings.strideRadius = strideRadius;
    settings.kinds.clear();
    for (size_t c = 0; c < creatures.size(); ++c)
        settings.kinds.push_back({strideMetres(c), creatures[c].walkCycleSeconds, creatures[c].idleCycleSeconds});
    // The means, for what reads the crowd's one gait (none of the steps do
    // while it has kinds).
    settings.walkStrideLength = walkStrideLength;
    settings.walkCycleSeconds = walkStrideLength / naturalSpeed;
    if (!creatures.empty()) settings.idleCycleSeconds = creatures.front().idleCycleSeconds;
}

Result<CrowdGait> measureCrowdGait(const CharacterAssets& assets, float height, float strideRadius) {
    if (assets.empty()) return fail("the crowd scene has no creatures to draw");
    CrowdGait gait;
    gait.strideRadius = strideRadius;
    double stride = 0.0, speed = 0.0;
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
        // Every creature as tall as the others, whatever its file's units
        // (a model in centimetres or of a giant stands `height` tall too); its
        // stride follows from its clip at that size.
        creature.scale = height / creature.height;
        creature.walkCycleSeconds = asset.clips[size_t(creature.walkClip)].duration();
        if (creature.idleClip >= 0 && creature.idleClip != creature.walkClip)
            creature.idleCycleSeconds = asset.clips[size_t(creature.idleClip)].duration();
        const double metres = double(creature.stride) * double(creature.scale);
        stride += metres / double(assets.size());
        speed += metres / double(creature.walkCycleSeconds) / double(assets.size());
    }
    gait.walkStrideLength = float(stride);
    gait.naturalSpeed = float(speed);
    return gait;
}

} // namespace tessera::runtime
