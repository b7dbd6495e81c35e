#include "Avoidance.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace tessera::crowd {
namespace {

constexpr float kEpsilon = 1e-5f;

float det(glm::vec2 a, glm::vec2 b) { return a.x * b.y - a.y * b.x; }

// The permitted half-plane for avoiding one neighbour: the truncated cone
// of relative velocities that collide within `horizon` (the velocity
// obstacle), and the smallest change u of the relative velocity that leaves
// it; the agent takes its share of u (half: reciprocal). Inlined: walls'
// corners use it too, and a call per neighbour cost 2% of a step.
[[gnu::always_inline]] inline VelocityLine neighbourLine(const AvoidanceQuery& q, const Neighbour& n) {
    const glm::vec2 p = n.offset;
    const glm::vec2 v = q.velocity - n.velocity;
    const float reach = q.radius + n.radius + q.comfort;
    const float distance2 = glm::dot(p, p), reach2 = reach * reach;
    VelocityLine line;
    glm::vec2 u;
    if (distance2 > reach2) {
        // w: from the centre of the cone's cut-off disc to v.
        const glm::vec2 w = v - p / q.horizon;
        const float w2 = glm::dot(w, w);
        const float along = glm::dot(w, p);
        if (along < 0.0f && along * along > reach2 * w2) {
            // Nearest the cut-off disc.
            const float wLength = std::sqrt(w2);
            const glm::vec2 unit = w / wLength;
            line.direction = {unit.y, -unit.x};
            u = (reach / q.horizon - wLength) * unit;
        } else {
            // Nearest one of the cone's legs.
            const float leg = std::sqrt(distance2 - reach2);
            if (det(p, w) > 0.0f)
                line.direction = glm::vec2(p.x * leg - p.y * reach, p.x * reach + p.y * leg) / distance2;
            else
                line.direction = -glm::vec2(p.x * leg + p.y * reach, -p.x * reach + p.y * leg) / distance2;
            u = glm::dot(v, line.direction) * line.direction - v;
        }
    } else {
        // Already overlapping: get apart within one step.
        const glm::vec2 w = v - p / q.timeStep;
        const float wLength = glm::length(w);
        const glm::vec2 unit = wLength > kEpsilon ? w / wLength : glm::vec2(1.0f, 0.0f);
        line.direction = {unit.y, -unit.x};
        u = (reach / q.timeStep - wLength) * unit;
    }
    line.point = q.velocity + n.share * u;
    return line;
}

// A face d metres beyond the agent's edge along n permits velocities with
// v . n <= d / wallHorizon (a full, not shared, responsibility): walking
// along it is free. A corner is a point standing still, avoided as a
// neighbour is but wholly by the agent: walking past it is free, only the
// cone of velocities that reach it within wallHorizon is not. (Taking every
// corner of the cells along a face as a face of its own would forbid
// walking along a wall at any speed that closes on the corners ahead.)
VelocityLine wallLine(const AvoidanceQuery& q, const WallPoint& wall) {
    const float distance = glm::length(wall.offset);
    const glm::vec2 n = distance > kEpsilon ? wall.offset / distance : glm::vec2(1.0f, 0.0f);
    const float gap = distance - q.radius;
    if (wall.corner && gap > 0.0f) {
        AvoidanceQuery still = q;
        still.comfort = 0.0f;
        still.horizon = q.wallHorizon;
        return neighbourLine(still, Neighbour{wall.offset, glm::vec2(0.0f), 0.0f, 0, 1.0f}); // all of u, not half
    }
    const float limit = gap >= 0.0f ? gap / q.wallHorizon : gap / q.timeStep;
    return {limit * n, {-n.y, n.x}};
}

// Optimum on line `index` within the speed disc and lines [0, index).
bool solveOnLine(std::span<const VelocityLine> lines, size_t index, float radius, glm::vec2 optimum,
                 bool directionOnly, glm::vec2& result) {
    const VelocityLine& line = lines[index];
    const float along = glm::dot(line.point, line.direction);
    const float discriminant = along * along + radius * radius - glm::dot(line.point, line.point);
    if (discriminant < 0.0f) return false; // the speed disc misses the line
    const float root = std::sqrt(discriminant);
    float tLeft = -along - root, tRight = -along + root;
    for (size_t i = 0; i < index; ++i) {
        const float denominator = det(line.direction, lines[i].direction);
        const float numerator = det(lines[i].direction, line.point - lines[i].point);
        if (std::abs(denominator) <= kEpsilon) {
            if (numerator < 0.0f) return false; // parallel and wholly forbidden
            continue;
        }
        const float t = numerator / denominator;
        if (denominator >= 0.0f) tRight = std::min(tRight, t);
        else tLeft = std::max(tLeft, t);
        if (tLeft > tRight) return false;
    }
    if (directionOnly) {
        result = line.point + (glm::dot(optimum, line.direction) > 0.0f ? tRight : tLeft) * line.direction;
    } else {
        const float t = std::clamp(glm::dot(line.direction, optimum - line.point), tLeft, tRight);
        result = line.point + t * line.direction;
    }
    return true;
}

// The velocity nearest `optimum` (or furthest along it, with directionOnly)
// in the speed disc and every half-plane; returns the index of the first
// line that made it infeasible, or lines.size().
size_t solvePlane(std::span<const VelocityLine> lines, float radius, glm::vec2 optimum, bool directionOnly,
                  glm::vec2& result) {
    if (directionOnly) result = optimum * radius;
    else if (glm::dot(optimum, optimum) > radius * radius) result = glm::normalize(optimum) * radius;
    else result = optimum;
    for (size_t i = 0; i < lines.size(); ++i) {
        if (det(lines[i].direction, lines[i].point - result) <= 0.0f) continue;
        const glm::vec2 before = result;
        if (!solveOnLine(lines, i, radius, optimum, directionOnly, result)) {
            result = before;
            return i;
        }
    }
    return lines.size();
}

// Infeasible: keep the first `hard` lines (walls), and minimise the largest
// violation of the others, starting at line `from`.
void leastViolation(std::span<const VelocityLine> lines, size_t hard, size_t from, float radius, glm::vec2& result,
                    std::vector<VelocityLine>& projected) {
    float distance = 0.0f;
    for (size_t i = from; i < lines.size(); ++i) {
        if (det(lines[i].direction, lines[i].point - result) <= distance) continue;
        projected.assign(lines.begin(), lines.begin() + std::ptrdiff_t(hard));
        for (size_t j = hard; j < i; ++j) {
            VelocityLine line;
            const float determinant = det(lines[i].direction, lines[j].direction);
            if (std::abs(determinant) <= kEpsilon) {
                if (glm::dot(lines[i].direction, lines[j].direction) > 0.0f) continue; // same way
                line.point = 0.5f * (lines[i].point + lines[j].point);
            } else {
                line.point = lines[i].point +
                             (det(lines[j].direction, lines[i].point - lines[j].point) / determinant) *
                                 lines[i].direction;
            }
            line.direction = glm::normalize(lines[j].direction - lines[i].direction);
            projected.push_back(line);
        }
        const glm::vec2 before = result;
        if (solvePlane(projected, radius, glm::vec2(-lines[i].direction.y, lines[i].direction.x), true, result) <
            projected.size())
            result = before; // only rounding can get here; keep the last good one
        distance = det(lines[i].direction, lines[i].point - result);
    }
}

} // namespace

glm::vec2 avoidCollisions(const AvoidanceQuery& q, std::span<const Neighbour> neighbours,
                          std::span<const WallPoint> walls, std::vector<VelocityLine>& lines) {
    lines.clear();
    for (const WallPoint& wall : walls) lines.push_back(wallLine(q, wall));
    const size_t hard = lines.size();
    for (const Neighbour& n : neighbours) lines.push_back(neighbourLine(q, n));
    glm::vec2 result(0.0f);
    const size_t failed = solvePlane(lines, q.maxSpeed, q.preferred, false, result);
    if (failed < lines.size()) {
        thread_local std::vector<VelocityLine> projected;
        leastViolation(lines, hard, std::max(failed, hard), q.maxSpeed, result, projected);
    }
    return result;
}

} // namespace tessera::crowd
