#pragma once
/// @file WalkerKind.h
/// One kind of walker in a crowd: the walk and idle clips of one drawn model,
/// as the simulation needs them to keep that model's feet planted.

namespace tessera::crowd {

/// The gait of one kind of agent (CrowdSettings::kinds). Agents of different
/// kinds share the crowd's preferred speeds and steering; each plays its own
/// clips, so each covers its own stride per walk cycle.
struct WalkerKind {
    /// Ground covered per walk-clip cycle at CrowdSettings::strideRadius
    /// (metres): the model's measured stride at the size it is drawn. An
    /// agent's stride scales with its radius, as its drawn size does.
    float walkStrideLength = 1.4f;
    /// Length of one walk-clip cycle (seconds): the clip plays at its own
    /// pace at walkStrideLength / walkCycleSeconds metres per second.
    float walkCycleSeconds = 1.1f;
    /// Length of one idle-clip cycle (seconds).
    float idleCycleSeconds = 2.5f;
};

} // namespace tessera::crowd
