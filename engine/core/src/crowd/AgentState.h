#pragma once
// Internal: the per-agent state a crowd keeps beyond what it publishes in
// CrowdAgents (structure-of-arrays too, same indices).

#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

namespace tessera::crowd {

/// Bits of AgentState::flags.
enum AgentFlag : uint8_t {
    kStaying = 1u << 0,     ///< arrived at a Stay goal; walks to `spot`, then idles
    kOnWalkable = 1u << 1,  ///< stood on passable ground at the start of the step
    kEscaping = 1u << 2,    ///< on impassable ground, walking off it
    kUnreachable = 1u << 3, ///< no route to the goal from here
    kArrived = 1u << 4,     ///< reached its goal during this step
    kCrowded = 1u << 5,     ///< a neighbour close enough to touch it by the end of the step
    kMoved = 1u << 6,       ///< separation's last iteration moved it
    kPushed = 1u << 7,      ///< separation's last push on it was one to go on for
};

struct AgentState {
    /// Avoidance's choice, swapped into CrowdAgents::velocity by
    /// integrate(); then (holding the old velocities) separation's second
    /// buffer of positions.
    std::vector<glm::vec2> nextVelocity;
    /// XZ after motion (written by steer()) and separation.
    std::vector<glm::vec2> moved;
    std::vector<glm::vec2> anchor;        ///< where it stood when it last made progress
    std::vector<float> stuckTime;         ///< seconds since it last got closer
    std::vector<float> fleeTime;          ///< seconds of fleeing left
    /// While fleeing, the impact it flees; while staying, its spot inside
    /// the goal (fleeing ends staying: the agent arrives anew after).
    std::vector<glm::vec2> spot;
    std::vector<uint16_t> arrivals;       ///< goals reached (seeds the next choice)
    std::vector<uint8_t> flags;
    /// Separation's marks per neighbour-grid cell: an agent sorted into it
    /// moved in the last iteration (read), in this one (written).
    std::vector<uint8_t> movedIn[2];

    void resize(size_t n) {
        nextVelocity.resize(n);
        moved.resize(n);
        anchor.resize(n);
        stuckTime.resize(n, 0.0f);
        fleeTime.resize(n, 0.0f);
        spot.resize(n);
        arrivals.resize(n, 0);
        flags.resize(n, 0);
    }
    /// Bytes held.
    size_t bytes() const {
        return (nextVelocity.capacity() + moved.capacity() + anchor.capacity() + spot.capacity()) * sizeof(glm::vec2) +
               (stuckTime.capacity() + fleeTime.capacity()) * sizeof(float) +
               arrivals.capacity() * sizeof(uint16_t) + flags.capacity() + movedIn[0].capacity() +
               movedIn[1].capacity();
    }
};

} // namespace tessera::crowd
