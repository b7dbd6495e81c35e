#pragma once
// Internal: local collision avoidance by optimal reciprocal collision
// avoidance (ORCA: van den Berg, Guy, Lin and Manocha, "Reciprocal n-body
// collision avoidance", 2011): each neighbour, and each nearby wall, cuts the
// plane of velocities in half; the new velocity is the permitted one nearest
// the preferred velocity, found by a 2-D linear program.

#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec2.hpp>

namespace tessera::crowd {

/// A neighbour as the agent sees it: position relative to the agent, its
/// velocity and radius.
struct Neighbour {
    glm::vec2 offset{0.0f};
    glm::vec2 velocity{0.0f};
    float radius = 0.0f;
    uint32_t agent = 0;  ///< its index, for the caller
    /// The share of the avoidance the agent takes (0.5: reciprocal, 1: all).
    float share = 0.5f;
};

/// A static obstacle near the agent, as the point of it nearest the agent
/// (relative to the agent): on a flat face, which the agent must not walk
/// into but may walk along, or a convex corner, which it may walk past.
struct WallPoint {
    glm::vec2 offset{0.0f};
    bool corner = false;
};

/// Everything one agent's choice depends on.
struct AvoidanceQuery {
    glm::vec2 velocity{0.0f};   ///< current
    glm::vec2 preferred{0.0f};  ///< where the field (or fleeing) wants to go
    float maxSpeed = 1.0f;
    float radius = 0.0f;
    float comfort = 0.0f;       ///< kept beyond the sum of radii
    float horizon = 2.0f;       ///< seconds ahead neighbours are avoided
    float wallHorizon = 1.0f;   ///< seconds ahead walls are avoided
    float timeStep = 1.0f / 30.0f;
};

/// A half-plane of permitted velocities: those to the left of `direction`
/// through `point` (right of it is forbidden).
struct VelocityLine {
    glm::vec2 point{0.0f};
    glm::vec2 direction{1.0f, 0.0f};
};

/// The velocity nearest `query.preferred`, no faster than `maxSpeed`, that
/// stays clear of every wall for wallHorizon seconds and takes half the
/// responsibility for avoiding every neighbour for `horizon` seconds. When
/// the constraints leave nothing (a dense jam), walls stay hard and the
/// velocity that violates the neighbour constraints least is taken.
/// `lines` is scratch space (kept by the caller to avoid allocation).
glm::vec2 avoidCollisions(const AvoidanceQuery& query, std::span<const Neighbour> neighbours,
                          std::span<const WallPoint> walls, std::vector<VelocityLine>& lines);

} // namespace tessera::crowd
