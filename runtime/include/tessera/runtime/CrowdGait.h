#pragma once
/// @file CrowdGait.h
/// How big the crowd scene draws its creatures and how fast they walk, so
/// that their feet follow the simulation. Every creature is drawn `height`
/// tall at the stride radius (taller or smaller with each agent's radius),
/// whatever the units of its file; each then walks its own stride, its walk
/// clip's ground per cycle (character::measureStride) at that size, as one
/// kind of walker of the crowd (crowd::WalkerKind, in creature order, so an
/// agent's kind, CrowdSettings::kindIndex, is its creature).

#include "tessera/runtime/CharacterAssets.h"
#include "tessera/core/Result.h"
#include "tessera/crowd/CrowdSettings.h"

#include <vector>

namespace tessera::runtime {

/// One creature as the crowd draws it.
struct CreatureGait {
    float height = 0.0f;           ///< rest-pose cage height, model units
    float stride = 0.0f;           ///< ground per walk cycle, model units (measureStride)
    float scale = 1.0f;            ///< draw scale of an agent of CrowdGait::strideRadius
    float walkCycleSeconds = 1.0f; ///< the walk clip's duration
    float idleCycleSeconds = 2.5f; ///< the idle clip's duration (2.5 s without one)
    int walkClip = -1;
    int idleClip = -1;
};

struct CrowdGait {
    float strideRadius = 0.4f;           ///< agent radius at which the scales hold (metres)
    float walkStrideLength = 0.0f;       ///< the creatures' mean ground per walk cycle at strideRadius (metres)
    float naturalSpeed = 0.0f;           ///< the creatures' mean speed with their walk clips at their own pace
    std::vector<CreatureGait> creatures; ///< one per asset, in CharacterAssets order

    /// Ground per walk cycle of creature `c` at strideRadius (metres).
    float strideMetres(size_t c) const { return creatures[c].stride * creatures[c].scale; }
    /// Sets the crowd's kinds of walker (one per creature, in order) and
    /// stride radius to this gait's.
    void apply(crowd::CrowdSettings& settings) const;
};

/// Measures every asset's walk clip ("walk", else its first) and sizes each
/// creature to stand `height` metres tall at agent radius `strideRadius`. An asset whose walk clip covers no ground is an error
/// naming its file.
Result<CrowdGait> measureCrowdGait(const CharacterAssets& assets, float height, float strideRadius);

} // namespace tessera::runtime
