#pragma once
// Internal: re-sorting the agents' arrays so that agents near each other on
// the ground are near each other in memory.

#include "AgentState.h"
#include "tessera/crowd/CrowdAgents.h"

#include <cstdint>
#include <span>

namespace tessera::crowd {

/// Permutes every per-agent array of `agents` and `state` so that new index
/// k holds the agent that was at `order[k]` (a permutation of all indices).
/// Arrays only alive within a step (nextVelocity, moved) are left alone.
/// Every phase of a step looks up grids at the agent's position and reads
/// its neighbours' data; with agents in memory in the order of the tiles
/// they stand on, both stay in cache.
void reorderAgents(CrowdAgents& agents, AgentState& state, std::span<const uint32_t> order, uint32_t threads);

} // namespace tessera::crowd
