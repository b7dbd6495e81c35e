#pragma once
// Internal: an agent's walk as its clip allows it: the ground one cycle of
// the walk clip covers, and the speeds at which the clip plays at a
// plausible pace, so that its feet stay planted.

#include "tessera/crowd/CrowdAgents.h"
#include "tessera/crowd/CrowdSettings.h"

#include <glm/vec2.hpp>

namespace tessera::crowd {

/// One agent's gait. The walk phase advances by distance / stride, so the
/// clip plays at speed / (stride / walkCycle) times its own pace:
/// keeping that rate within [minWalkRate, maxWalkRate] means walking no
/// slower than `slowest` and no faster than `fastest`, or standing still.
struct AgentGait {
    float stride = 1.0f;       ///< metres per walk cycle
    float slowest = 0.0f;      ///< m/s
    float fastest = 0.0f;      ///< m/s
    float walkCycle = 1.0f;    ///< seconds per walk cycle at the clip's own pace
    float idleCycle = 1.0f;    ///< seconds per idle cycle

    /// The gait of the agent with id `id` (its kind, CrowdSettings::kindOf)
    /// and `radius` (strides scale with the radius).
    static AgentGait of(const CrowdSettings& settings, uint32_t id, float radius) {
        const WalkerKind kind = settings.kindOf(id);
        AgentGait gait;
        gait.stride = kind.walkStrideLength * radius / settings.strideRadius;
        gait.walkCycle = kind.walkCycleSeconds;
        gait.idleCycle = kind.idleCycleSeconds;
        const float natural = gait.stride / kind.walkCycleSeconds;
        gait.slowest = settings.minWalkRate * natural;
        gait.fastest = settings.maxWalkRate * natural;
        return gait;
    }

    /// The velocity to take from `limited` (the chosen velocity after the
    /// acceleration limit) when `chosen` is what avoidance asked for: at
    /// least the slowest walk while it wants to walk (a first step from
    /// standing is one), braking from there to a stand when it wants to
    /// stop, never faster than the fastest walk.
    glm::vec2 walkable(glm::vec2 limited, glm::vec2 chosen) const;

    /// After a step that moved the agent `distance` metres on the ground:
    /// the walk clip while it walks (`walking`: a velocity of its own), its
    /// phase advanced by distance / stride at most maxWalkRate times the
    /// clip's pace; the idle clip, by time, while it stands.
    void advance(const CrowdSettings& settings, bool walking, float distance, AgentClip& clip, float& phase) const;
};

} // namespace tessera::crowd
