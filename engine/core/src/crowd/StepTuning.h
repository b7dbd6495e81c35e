#pragma once
// Internal: the crowd step's constants that more than one of its files use.

#include <cstdint>

namespace tessera::crowd {

// Agents per parallel task: enough work to amortise scheduling, small
// enough to balance. Fixed, so the split never depends on the thread count.
inline constexpr uint32_t kGrain = 256;
// How far an agent may move in one step plus what separation may add, for
// neighbour queries made with the grid built before the step moved anyone.
inline constexpr float kQuerySlack = 0.15f;

} // namespace tessera::crowd
