#include "AgentGait.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace tessera::crowd {

glm::vec2 AgentGait::walkable(glm::vec2 limited, glm::vec2 chosen) const {
    const float speed = glm::length(limited);
    if (speed > fastest) return limited * (fastest / speed);
    if (speed >= slowest) return limited;
    // Slower than the clip can walk without sliding: below half the slowest
    // walk the agent means to stop, and does once it has braked to the
    // slowest walk; above, it walks at the slowest (from a stand, that is
    // its first step). Turning back, it stops first and sets off the other
    // way from a stand: kept at the slowest walk along the way it was
    // going, it could never turn round.
    const float wanted = glm::length(chosen);
    if (wanted < 0.5f * slowest) return glm::vec2(0.0f);
    if (speed <= 1e-6f) return chosen * (slowest / wanted);
    if (glm::dot(limited, chosen) <= 0.0f) return glm::vec2(0.0f);
    return limited * (slowest / speed);
}

void AgentGait::advance(const CrowdSettings& s, bool walking, float distance, AgentClip& clip, float& phase) const {
    if (walking) {
        // The ground covered (pushes by others included), so the feet do
        // not slide; a push that would play the clip faster than its
        // fastest is taken as slide instead.
        clip = AgentClip::Walk;
        phase += std::min(distance / stride, s.maxWalkRate * s.timeStep / walkCycle);
    } else {
        clip = AgentClip::Idle;
        phase += s.timeStep / idleCycle;
    }
    phase -= std::floor(phase);
}

} // namespace tessera::crowd
