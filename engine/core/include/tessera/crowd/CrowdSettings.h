#pragma once
/// @file CrowdSettings.h
/// Every tunable of the crowd simulation, with the defaults the demo and the
/// benchmark use. docs/CROWD.md explains each group of settings.

#include "tessera/crowd/WalkerKind.h"

#include <cstdint>
#include <vector>

namespace tessera::crowd {

struct CrowdSettings {
    // --- Time and threads -------------------------------------------------
    /// Seconds per step. The simulation always advances by this fixed step,
    /// so a seed and a step count give the same state on any machine.
    float timeStep = 1.0f / 30.0f;
    /// Threads for the parallel loops (0: every hardware thread). The state
    /// after N steps is bit-identical for any value.
    uint32_t threads = 0;

    // --- Navigation grid and cost -----------------------------------------
    /// Metres per navigation cell. The grid covers the whole terrain; the
    /// default matches the content height map's 4 m sample spacing.
    float cellSize = 4.0f;
    /// Ground steeper than this is impassable (degrees). On the content
    /// map's eroded mountains, 35 degrees leaves half the map in one
    /// connected walkable area.
    float maxSlopeDegrees = 35.0f;
    /// Walking speed at the slope limit, as a fraction of the flat-ground
    /// speed; speed falls off quadratically in between.
    float slopeSpeedAtLimit = 0.35f;
    /// Density (agents per square metre) below which crowding costs nothing,
    /// and at which it costs the most.
    float densityMin = 0.5f;
    float densityMax = 2.5f;
    /// Walking against a crowd at densityMax (or into one standing still)
    /// costs up to 1 + this times the terrain cost; walking with it, nothing
    /// extra.
    float densityCostWeight = 8.0f;
    /// The speed the crowd's mean velocity is measured against (m/s): a
    /// stream moving this fast is a free walk.
    float flowSpeed = 1.2f;
    /// Seconds between density splats into the cost field.
    float densityUpdateSeconds = 0.5f;

    // --- Potential fields -------------------------------------------------
    /// Tile solves (16 x 16 cells each) the incremental eikonal solver may
    /// spend per step over all goal groups after the initial solve. Bounds the
    /// cost of re-solving after density changes and craters; leftover work
    /// carries over to the next steps, nearest the goals first.
    uint32_t fieldTileBudget = 128;

    // --- Craters ----------------------------------------------------------
    /// A fresh crater is impassable for this long (seconds)...
    float hazardSeconds = 20.0f;
    /// ...out to its radius plus this margin (metres).
    float hazardMargin = 3.0f;
    /// Agents within this multiple of the hazard radius flee the impact...
    float fleeRadiusFactor = 1.6f;
    /// ...for this long (seconds), at this multiple of their preferred speed.
    float fleeSeconds = 3.0f;
    float fleeSpeedFactor = 1.8f;

    // --- Local avoidance --------------------------------------------------
    /// Neighbours are looked for within this distance (metres)...
    float neighbourRadius = 3.0f;
    /// ...and at most this many of the nearest are considered.
    uint32_t maxNeighbours = 10;
    /// Collisions further ahead than this (seconds) are ignored. One second,
    /// not two: agents close up behind those ahead in a queue instead of
    /// braking for them from far back (docs/CROWD.md, "Local avoidance").
    float horizonSeconds = 1.0f;
    /// Personal space kept beyond the sum of radii while steering (metres).
    /// Small: 0.08 m took a fifth of a bottleneck's flow (one group through a
    /// 12 m gap: 14 agents a second, 17.5 with 0.02), and the overlap stays
    /// within 5% of the radii (measured 3% in the dense counterflow).
    float comfortMargin = 0.02f;
    /// Position-correction iterations resolving residual overlaps.
    uint32_t separationIterations = 4;
    /// Acceleration limit (m/s^2) and heading turn-rate limit (radians/s).
    float maxAcceleration = 4.0f;
    float maxTurnRate = 5.0f;

    /// Height of an agent's box for culling (metres above its feet).
    float agentHeight = 2.0f;

    // --- Animation ---------------------------------------------------------
    /// Ground covered per walk-clip cycle at radius `strideRadius` (metres),
    /// e.g. character::measureStride of the drawn model; an agent's stride
    /// scales with its radius. The walk phase advances by the ground covered
    /// / stride, so feet stay planted.
    float walkStrideLength = 1.4f;
    float strideRadius = 0.4f;
    /// Length of one walk-clip cycle (seconds): the clip plays at its own
    /// pace at stride / walkCycleSeconds metres per second.
    float walkCycleSeconds = 1.1f;
    /// The walk clip plays between these multiples of its own pace. As the
    /// phase follows the ground, an agent walks between minWalkRate and
    /// maxWalkRate times its stride / walkCycleSeconds, or stands (idle).
    float minWalkRate = 0.4f;
    float maxWalkRate = 2.2f;
    /// Length of one idle-clip cycle (seconds).
    float idleCycleSeconds = 2.5f;
    /// Kinds of walker, e.g. one per drawn model: the agent with id `id` is
    /// of kind `id % kinds.size()` (kindOf) and walks with that kind's stride
    /// and clip lengths instead of walkStrideLength, walkCycleSeconds and
    /// idleCycleSeconds above, which hold for every agent while this is
    /// empty (the default).
    std::vector<WalkerKind> kinds;

    /// The kind of the agent with id `id`: its index in `kinds` (0 while
    /// `kinds` is empty). A host drawing one model per kind picks the model
    /// by it.
    uint32_t kindIndex(uint32_t id) const { return kinds.empty() ? 0u : id % uint32_t(kinds.size()); }
    /// The gait of the agent with id `id`: its kind's, or the one above.
    WalkerKind kindOf(uint32_t id) const {
        return kinds.empty() ? WalkerKind{walkStrideLength, walkCycleSeconds, idleCycleSeconds} : kinds[kindIndex(id)];
    }

    // --- Progress -----------------------------------------------------------
    /// An agent that wants to walk but has not got `stuckProgress` metres
    /// from where it was for `stuckSeconds` counts as stuck and sidesteps.
    float stuckSeconds = 3.0f;
    float stuckProgress = 1.0f;
};

} // namespace tessera::crowd
