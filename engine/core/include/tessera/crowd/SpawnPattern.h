#pragma once
/// @file SpawnPattern.h
/// Where, how many and which agents a crowd starts with.

#include "tessera/crowd/Region.h"

#include <cstdint>

namespace tessera::crowd {

/// `count` agents placed uniformly at random (from `seed`) on the walkable
/// ground of `region`, without overlapping each other. Each agent's radius
/// and preferred speed are drawn from the given ranges.
struct SpawnPattern {
    /// Goal group index for every agent of the pattern; kEveryGroup deals the
    /// agents out over all groups in turn.
    static constexpr uint32_t kEveryGroup = UINT32_MAX;

    Region region;
    uint32_t count = 0;
    uint32_t seed = 1;
    uint32_t goalGroup = kEveryGroup;
    float radiusMin = 0.35f; ///< metres
    float radiusMax = 0.45f;
    float speedMin = 1.1f;   ///< metres per second on flat ground
    float speedMax = 1.5f;
    /// Place agents only where their goal can be reached from (not on
    /// islands of walkable ground cut off by steep slopes). Without it,
    /// agents with no route idle where they stand (CrowdStats::unreachable).
    bool reachableOnly = true;
};

} // namespace tessera::crowd
