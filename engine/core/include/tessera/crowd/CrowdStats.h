#pragma once
/// @file CrowdStats.h
/// What a crowd reports about itself after each step: counts, progress,
/// solver backlog, time per phase and memory.

#include <cstddef>
#include <cstdint>

namespace tessera::crowd {

/// Counts after the last step.
struct CrowdStats {
    uint32_t agents = 0;
    uint32_t walking = 0;      ///< playing the walk clip
    uint32_t fleeing = 0;      ///< running from a fresh impact
    uint32_t escaping = 0;     ///< standing on impassable ground, walking off it
    uint32_t unreachable = 0;  ///< no route to their goal: they idle where they stand
    uint32_t staying = 0;      ///< arrived at a Stay goal
    uint32_t stuck = 0;        ///< no progress for CrowdSettings::stuckSeconds
    float maxStuckSeconds = 0.0f;
    uint64_t arrivals = 0;     ///< goal regions reached since the start
    uint32_t activeHazards = 0;
    uint32_t fieldTilesSolved = 0;  ///< tile solves this step
    uint32_t fieldTilesWaiting = 0; ///< tiles still to settle
};

/// Milliseconds spent in each phase of the last step (steady clock).
struct CrowdTimings {
    double fields = 0.0;      ///< craters, hazards, density splat, eikonal solves
    double avoidance = 0.0;   ///< neighbour grid, steering, ORCA
    double integration = 0.0; ///< motion, separation, terrain following, animation, bounds
    double total() const { return fields + avoidance + integration; }
};

/// Pairs of agents that overlap, measured over the whole crowd.
struct OverlapReport {
    uint32_t pairs = 0;        ///< pairs closer than 95% of the sum of their radii
    float worst = 0.0f;        ///< largest overlap as a fraction of the sum of radii
    uint32_t overlapping = 0;  ///< agents in at least one such pair
};

/// Memory held by a crowd.
struct CrowdMemory {
    size_t agentBytes = 0;  ///< per-agent state and scratch (everything that scales with agents)
    size_t fieldBytes = 0;  ///< navigation grid, costs, potentials, bins
    double bytesPerAgent = 0.0;
};

} // namespace tessera::crowd
