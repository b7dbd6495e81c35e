#include "NullCrowd.h"

#include "tessera/backend/CrowdChecks.h"

namespace tessera::backends {

NullCrowd::NullCrowd(std::vector<Creature> creatures, uint32_t clips, uint32_t maxInstances, uint32_t maxIds)
    : mCreatures(std::move(creatures)), mClips(clips), mMaxInstances(maxInstances),
      mState(maxIds, shader::tsLodStateNone()) {}

backend::CrowdTierCounts NullCrowd::draw(const backend::CrowdDrawInfo& draw) {
    backend::CrowdTierCounts counts;
    for (auto& list : mTiers.instances) list.clear();
    const shader::CrowdLodParams& p = draw.lod;
    const size_t n = std::min<size_t>(draw.instances.size(), mMaxInstances);
    for (uint32_t i = 0; i < n; ++i) {
        const shader::CrowdInstance& instance = draw.instances[i];
        if (!backend::crowdInstanceValid(instance, uint32_t(mState.size()), uint32_t(mCreatures.size()), mClips))
            continue;
        uint32_t& state = mState[instance.ids.x];
        state = shader::tsLodUpdate(state, instance.sphere, p,
                                    draw.occluders.empty() ? nullptr : draw.occluders.data());
        const uint32_t tier = shader::tsLodStateTier(state);
        if (tier == TS_LOD_NONE) continue; // out of view or behind the terrain
        const Creature& creature = mCreatures[instance.ids.y];
        auto add = [&](uint32_t t) {
            mTiers.instances[t].push_back(i);
            ++counts.instances[t];
            // Before tessellation, as the GPU backends count them (the near
            // tier's cage; tessellation's output is the pass's statistics).
            counts.triangles[t] += t == TS_LOD_IMPOSTOR ? 2u
                                   : t == TS_LOD_FAR    ? creature.farTriangles
                                   : t == TS_LOD_MIDDLE ? creature.middleTriangles
                                                        : creature.cageTriangles;
        };
        add(tier);
        if (shader::tsLodStateFade(state) > 0u) add(shader::tsLodStatePrevious(state));
    }
    return counts;
}

} // namespace tessera::backends
