#pragma once
/// @file CrowdGait.h
/// How big the crowd scene draws its creatures and how fast they walk, so
/// that their feet follow the simulation. The crowd advances a walker's clip
/// phase by distance / stride, one stride for the whole crowd (scaled by each
/// agent's radius); each creature's walk clip covers its own stride
/// (character::measureStride). Drawing creature c at walkStrideLength /
/// stride(c) times its size makes every creature cover the crowd's stride per
/// cycle; walkStrideLength is chosen so the creatures stand `height` tall on
/// average.

#include "tessera/runtime/CharacterAssets.h"
#include "tessera/core/Result.h"
#include "tessera/crowd/CrowdSettings.h"

#include <vector>

namespace tessera::runtime {

/// One creature as the crowd draws it.
struct CreatureGait {
    float height = 0.0f; ///< rest-pose cage height, model units
    float stride = 0.0f; ///< ground per walk cycle, model units (measureStride)
    float scale = 1.0f;  ///< draw scale of an agent of CrowdGait::strideRadius
    int walkClip = -1;
    int idleClip = -1;
};

struct CrowdGait {
    float strideRadius = 0.4f;           ///< agent radius at which walkStrideLength and the scales hold (metres)
    float walkStrideLength = 0.0f;       ///< ground per walk cycle at strideRadius (metres), every creature scaled
    float naturalSpeed = 0.0f;           ///< walkStrideLength per walk-clip duration: clips play at their own pace
    float idleCycleSeconds = 2.5f;       ///< the idle clip's duration
    std::vector<CreatureGait> creatures; ///< one per asset, in CharacterAssets order

    /// Sets the crowd's stride, walk pace and idle cycle to this gait's.
    void apply(crowd::CrowdSettings& settings) const;
};

/// Measures every asset's walk clip ("walk", else its first) and sizes the
/// creatures to stand `height` metres tall on average at agent radius
/// `strideRadius`. An asset whose walk clip covers no ground is an error
/// naming its file.
Result<CrowdGait> measureCrowdGait(const CharacterAssets& assets, float height, float strideRadius);

} // namespace tessera::runtime
