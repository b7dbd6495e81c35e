#include "tessera/crowd/Crowd.h"

#include "AgentBins.h"
#include "AgentGait.h"
#include "AgentOrder.h"
#include "AgentState.h"
#include "Avoidance.h"
#include "Navigation.h"
#include "NeighbourGrid.h"
#include "StepTuning.h"
#include "tessera/crowd/FloorToInt.h"
#include "tessera/core/ParallelFor.h"
#include "tessera/core/Random.h"
#include "tessera/profiler/CpuScope.h"
#include "tessera/scene/SceneGraph.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>

namespace tessera::crowd {
namespace {

// Walls (impassable cells) are avoided this many seconds ahead; the nearest
// kMaxWalls cells within reach count.
constexpr float kWallHorizon = 1.0f;
constexpr uint32_t kMaxWalls = 8;
// Steps between re-sorting the agents in memory by where they stand.
constexpr uint64_t kReorderSteps = 32;
// Agents per range of the statistics' parallel count.
constexpr uint32_t kStatsGrain = 16384;
// An arrival at a Stay goal picks its spot up to this far on (metres)...
constexpr float kStaySpotRange = 8.0f;
// ...and has reached it when closer than this.
constexpr float kStaySpotReach = 0.3f;
// A stuck agent sidesteps this far off its preferred direction (radians):
// to the right where others want to come through, else first to the right,
// swapping sides every kSidestepPeriod seconds.
constexpr float kSidestepAngle = 1.1f;
constexpr float kSidestepPeriod = 2.0f;
// Walkers wanting to come the other way around a point kLaneLookAhead
// metres ahead turn an agent's preferred direction to the right by
// kLaneShift radians per agent per square metre, up to kMaxLaneShift:
// opposing streams settle into lanes instead of meeting head on. Gently
// (0.3, not 0.9): a crowd waiting at a passage that turned aside hard for
// the stream coming out stood off the passage, left its own lane a single
// file and the other group the whole width (measured: 0.9 put 36% and 38%
// of the counterflow through within twice their free walk, 0.3 37% and 40%,
// 0: 34% and 28%).
constexpr float kLaneLookAhead = 1.0f;
constexpr float kLaneShift = 0.3f;
constexpr float kMaxLaneShift = 1.3f;
// Oncoming agents per square metre that give a stuck agent a side to take.
constexpr float kOncomingSide = 0.05f;
// How much more an agent held up gives way than one walking at its
// preferred speed (ORCA's share of the avoidance, in proportion).
constexpr float kHeldUpYield = 4.0f;

using Clock = std::chrono::steady_clock;
double millisecondsSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

glm::vec2 rotate(glm::vec2 v, float angle) {
    const float c = std::cos(angle), s = std::sin(angle);
    return {v.x * c - v.y * s, v.x * s + v.y * c};
}

float wrapAngle(float a) {
    constexpr float pi = std::numbers::pi_v<float>;
    return a - 2.0f * pi * float(floorToInt((a + pi) * (0.5f / pi)));
}

// atan2(y, x) for x, y not both zero, within 2e-6 radians: an odd minimax
// polynomial for atan on [0, 1], then the octant. Only the heading uses it,
// which nothing in the simulation reads back; libm's atan2f was 4% of a
// step's instructions.
float headingAngle(float y, float x) {
    constexpr float pi = std::numbers::pi_v<float>;
    const float ax = std::abs(x), ay = std::abs(y);
    const float t = std::min(ax, ay) / std::max(ax, ay), t2 = t * t;
    float r = t * (0.99997726f +
                   t2 * (-0.33262347f + t2 * (0.19354346f + t2 * (-0.11643287f + t2 * (0.05265332f + t2 * -0.01172120f)))));
    if (ay > ax) r = 0.5f * pi - r;
    if (x < 0.0f) r = pi - r;
    return y < 0.0f ? -r : r;
}

glm::vec2 xz(const glm::vec3& p) { return {p.x, p.z}; }

// How much an agent gives way: 1 walking at its preferred speed, up to
// 1 + kHeldUpYield standing.
float yieldWeight(glm::vec2 velocity, float preferredSpeed) {
    return 1.0f + kHeldUpYield * std::max(0.0f, 1.0f - glm::length(velocity) / preferredSpeed);
}

} // namespace

void Crowd::step() {
    const auto start = Clock::now();
    mTime += mSettings.timeStep;
    {
        TESSERA_CPU_SCOPE("crowd.fields");
        reactToTerrain();
        mNavigation->expireHazards(mTime);
        const uint64_t densitySteps =
            std::max<uint64_t>(1, uint64_t(std::lround(mSettings.densityUpdateSeconds / mSettings.timeStep)));
        if (mSteps % densitySteps == 0) splatDensity();
        mStats.fieldTilesSolved = mNavigation->solve();
    }
    const auto fieldsDone = Clock::now();
    {
        TESSERA_CPU_SCOPE("crowd.avoidance");
        mNeighbours->build(mAgents.position, tileAgents(), neighbourCellSize(), mSettings.threads);
        steer();
    }
    const auto avoidanceDone = Clock::now();
    {
        TESSERA_CPU_SCOPE("crowd.integration");
        integrate();
        separate();
        finishStep();
        publish();
    }
    ++mSteps;
    mTimings.fields = std::chrono::duration<double, std::milli>(fieldsDone - start).count();
    mTimings.avoidance = std::chrono::duration<double, std::milli>(avoidanceDone - fieldsDone).count();
    mTimings.integration = millisecondsSince(avoidanceDone);
}

TileAgents Crowd::tileAgents() const {
    const NavGrid& grid = navGrid();
    return {mBins->order(), mBins->starts(), mBins->occupiedTiles(), grid.cellSize(), grid.width(), grid.height()};
}

float Crowd::neighbourCellSize() const {
    // About two agents per cell where they are: smaller cells waste
    // lookups on empty cells in a sparse crowd, larger ones make a dense
    // crowd's queries wade through agents out of reach. The ground they
    // stand on is measured in occupied tiles (from the last step's bins).
    const float smallest = 2.0f * mLargestRadius + kQuerySlack;
    const float tile = float(NavGrid::kTileCells) * navGrid().cellSize();
    const float area = float(mBins->occupiedTiles().size()) * tile * tile;
    const float perCell = mAgents.size() ? std::sqrt(2.0f * area / float(mAgents.size())) : smallest;
    return std::clamp(perCell, smallest, std::max(smallest, mSettings.neighbourRadius));
}

void Crowd::splatDensity() {
    // Where each agent wants to go: down its field, unless it stays, flees,
    // escapes or has nowhere to go (then its velocity says enough). Kept in
    // the separation's scratch buffer, free until steer() fills it.
    AgentState& st = *mState;
    const CrowdAgents& a = mAgents;
    const Navigation& nav = *mNavigation;
    std::vector<glm::vec2>& intentions = st.nextVelocity;
    core::parallelForRanges(uint32_t(a.size()), kGrain, mSettings.threads, [&](core::IndexRange range) {
        for (uint32_t i = range.begin; i < range.end; ++i) {
            const bool walking = !(st.flags[i] & (kStaying | kEscaping | kUnreachable)) && st.fleeTime[i] <= 0.0f;
            intentions[i] = walking ? nav.field(a.goalGroup[i]).descent(xz(a.position[i])) : glm::vec2(0.0f);
        }
    });
    mNavigation->updateDensity(*mBins, a.position, a.velocity, intentions);
}

void Crowd::reactToTerrain() {
    const std::span<const terrain::CraterSplat> history = mTerrain.splatHistory();
    for (; mSplatsSeen < history.size(); ++mSplatsSeen) {
        const Hazard hazard = mNavigation->addCrater(mTerrain, history[mSplatsSeen], mTime);
        // Agents near the impact run from it (those in its tiles or around).
        const float reach = hazard.radius * mSettings.fleeRadiusFactor;
        const NavGrid& grid = navGrid();
        const CellRect cells = grid.cellsTouching(hazard.center - reach, hazard.center + reach);
        if (cells.empty()) continue;
        constexpr int32_t n = int32_t(NavGrid::kTileCells);
        for (int32_t tj = cells.j0 / n; tj <= cells.j1 / n; ++tj)
            for (int32_t ti = cells.i0 / n; ti <= cells.i1 / n; ++ti)
                for (uint32_t a : mBins->agentsIn(uint32_t(tj) * grid.tilesX() + uint32_t(ti)))
                    if (glm::distance(xz(mAgents.position[a]), hazard.center) < reach) {
                        mState->fleeTime[a] = mSettings.fleeSeconds;
                        mState->spot[a] = hazard.center;
                        mState->flags[a] &= ~kStaying;
                    }
    }
}

void Crowd::steer() {
    const uint32_t count = uint32_t(mAgents.size());
    const CrowdSettings& s = mSettings;
    const Navigation& nav = *mNavigation;
    const CostField& cost = nav.cost();
    const NavGrid& grid = nav.grid();
    const float closeRadius = 0.5f * s.neighbourRadius;
    // With cells as large as the close radius, looking close first saves
    // nothing: one look over the whole radius.
    const bool sparse = neighbourCellSize() >= closeRadius;
    const float maxStep = mFastest * s.fleeSpeedFactor * s.timeStep;
    const float maxDelta = s.maxAcceleration * s.timeStep;
    const float dt = s.timeStep;
    const float maxTurn = s.maxTurnRate * dt;
    AgentState& st = *mState;
    CrowdAgents& a = mAgents;
    // What integrate() did, once an agent's new velocity is known: its spot
    // after moving (separation's input), its heading and what is left of
    // its fleeing. Here, in the loop that already has the agent in cache,
    // rather than a pass of its own over every agent. The velocity itself
    // waits in nextVelocity (neighbours still read the old one).
    auto move = [&](uint32_t i, glm::vec2 v) {
        st.nextVelocity[i] = v;
        st.moved[i] = xz(a.position[i]) + v * dt;
        if (v != glm::vec2(0.0f)) {
            const float turn = wrapAngle(headingAngle(v.x, v.y) - a.heading[i]);
            a.heading[i] = wrapAngle(a.heading[i] + std::clamp(turn, -maxTurn, maxTurn));
        }
        st.fleeTime[i] = std::max(0.0f, st.fleeTime[i] - dt);
    };
    core::parallelForRanges(count, kGrain, s.threads, [&](core::IndexRange range) {
        NearAgent nearby[NeighbourGrid::kMaxNearest];
        Neighbour near[NeighbourGrid::kMaxNearest];
        WallPoint walls[kMaxWalls];
        float wallDistance[kMaxWalls];
        std::vector<VelocityLine> lines;
        for (uint32_t i = range.begin; i < range.end; ++i) {
            const glm::vec2 p = xz(a.position[i]);
            uint8_t flags = st.flags[i] & ~(kOnWalkable | kEscaping | kUnreachable | kCrowded);
            const bool walkable = cost.passableAt(p);
            if (walkable) flags |= kOnWalkable;
            const float speed = a.preferredSpeed[i];
            glm::vec2 preferred(0.0f);
            bool stuck = false, walkingField = false;
            if (st.fleeTime[i] > 0.0f) {
                const glm::vec2 away = p - st.spot[i];
                const float length = glm::length(away);
                preferred = (length > 1e-4f ? away / length : glm::vec2(1.0f, 0.0f)) * speed * s.fleeSpeedFactor;
            } else if (!walkable) {
                flags |= kEscaping;
                preferred = nav.escapeDirection(p) * speed;
            } else if (flags & kStaying) {
                // A spot others stand on is given up for another further in.
                if (st.stuckTime[i] > s.stuckSeconds) {
                    Random random(a.id[i], ++st.arrivals[i]);
                    const Region& region = mGoals[a.goalGroup[i]].region;
                    pickSpot(i, glm::normalize(region.center - p + 1e-6f), random);
                    st.stuckTime[i] = 0.0f;
                    st.anchor[i] = p;
                }
                const glm::vec2 to = st.spot[i] - p;
                const float length = glm::length(to);
                if (length > kStaySpotReach) preferred = to / length * std::min(speed, length);
            } else {
                const PotentialField& field = nav.field(a.goalGroup[i]);
                glm::vec2 direction = field.descent(p);
                if (direction == glm::vec2(0.0f) && !field.goal().contains(p)) flags |= kUnreachable;
                stuck = st.stuckTime[i] > s.stuckSeconds;
                walkingField = true;
                const glm::ivec2 c = grid.cellOf(p);
                preferred = direction * speed * grid.speedFactor(grid.index(uint32_t(c.x), uint32_t(c.y)));
            }
            // Standing agents stay put (others avoid them): no neighbours to
            // look at here; separation looks at them all the same, as
            // someone may be pushing.
            if (preferred == glm::vec2(0.0f) && a.velocity[i] == glm::vec2(0.0f)) {
                st.flags[i] = flags | kCrowded;
                move(i, glm::vec2(0.0f));
                continue;
            }
            // The nearest neighbours, by distance then index.
            // Looked for close by first: in a dense crowd that finds them all
            // at a fraction of the cost; the rest of the radius only when it
            // did not.
            const uint32_t found = mNeighbours->nearest(p, i, sparse ? s.neighbourRadius : closeRadius, s.neighbourRadius,
                                                  s.maxNeighbours, nearby);
            // Whether anybody is near enough to touch it by the end of the
            // step (both walking at most maxStep): separation looks only at
            // such agents.
            const float touch = a.radius[i] + mLargestRadius + 2.0f * maxStep;
            if (found > 0 && nearby[0].distance2 < touch * touch) flags |= kCrowded;
            st.flags[i] = flags;
            // Walking its field, an agent keeps right of those who want to
            // come the other way just ahead (standing or walking): the more
            // of them, the further right, up to a sidestep. Both sides turn
            // the same way, so they pass instead of pressing into each
            // other, and a crowd waiting at a passage moves aside for those
            // coming out of it. (Fleeing, or walking off impassable ground,
            // it takes the way out it has.) A stuck agent sidesteps: to the
            // right too where others want to come through, else right and
            // left in turn (a jam of its own side or at a wall has no side
            // to prefer).
            const float preferredSpeed = glm::length(preferred);
            if (walkingField && preferredSpeed > 0.0f) {
                const glm::vec2 ahead = preferred / preferredSpeed;
                const float oncoming = cost.oncoming(p + ahead * kLaneLookAhead, ahead);
                float shift = std::min(kMaxLaneShift, kLaneShift * oncoming);
                if (stuck) {
                    const bool left = uint32_t((st.stuckTime[i] - s.stuckSeconds) / kSidestepPeriod) & 1u;
                    shift = oncoming > kOncomingSide ? std::max(shift, kSidestepAngle)
                                                     : (left ? -kSidestepAngle : kSidestepAngle);
                }
                if (shift != 0.0f) preferred = rotate(preferred, shift);
            }
            // No faster than the walk clip plays without sliding.
            const AgentGait gait = AgentGait::of(s, a.id[i], a.radius[i]);
            if (const float wanted = glm::length(preferred); wanted > gait.fastest) preferred *= gait.fastest / wanted;
            const float maxSpeed = std::min(std::max(glm::length(preferred), 0.25f * speed), gait.fastest);
            // Walls: the nearest points of the impassable cells within reach
            // (none for an agent walking off impassable ground), only where
            // they face the agent: a face hidden behind the impassable cell
            // next to it, or a corner inside a straight wall, is left to that
            // cell's own face.
            uint32_t wallCount = 0;
            if (walkable) {
                auto blocked = [&](int32_t ci, int32_t cj) {
                    return !grid.inGrid(ci, cj) || !cost.passable(grid.index(uint32_t(ci), uint32_t(cj)));
                };
                const float wallReach = a.radius[i] + maxSpeed * kWallHorizon;
                const glm::ivec2 c0 = grid.cellOf(p - wallReach), c1 = grid.cellOf(p + wallReach);
                for (int32_t cj = c0.y; cj <= c1.y; ++cj)
                    for (int32_t ci = c0.x; ci <= c1.x; ++ci) {
                        if (!blocked(ci, cj)) continue;
                        const glm::vec2 lo = glm::vec2(float(ci), float(cj)) * grid.cellSize();
                        const glm::vec2 hi = lo + grid.cellSize();
                        const int32_t sx = p.x < lo.x ? -1 : p.x > hi.x ? 1 : 0;
                        const int32_t sz = p.y < lo.y ? -1 : p.y > hi.y ? 1 : 0;
                        if ((sx == 0 && sz == 0) || (sx != 0 && blocked(ci + sx, cj)) || (sz != 0 && blocked(ci, cj + sz)))
                            continue;
                        const glm::vec2 offset = glm::clamp(p, lo, hi) - p;
                        const float d = glm::dot(offset, offset);
                        if (d > wallReach * wallReach || (wallCount == kMaxWalls && d >= wallDistance[kMaxWalls - 1]))
                            continue;
                        uint32_t k = wallCount < kMaxWalls ? wallCount++ : kMaxWalls - 1;
                        while (k > 0 && wallDistance[k - 1] > d) {
                            walls[k] = walls[k - 1];
                            wallDistance[k] = wallDistance[k - 1];
                            --k;
                        }
                        walls[k] = {offset, sx != 0 && sz != 0};
                        wallDistance[k] = d;
                    }
            }
            // Who gives way: an agent held up (slower than it wants) more than
            // one walking freely, so a stream comes through a waiting crowd
            // rather than the crowd pressing into the stream. The neighbours'
            // velocities and radii are read only for the few kept.
            const float weight = yieldWeight(a.velocity[i], speed);
            for (uint32_t k = 0; k < found; ++k) {
                const uint32_t j = nearby[k].agent;
                const float share = weight / (weight + yieldWeight(a.velocity[j], a.preferredSpeed[j]));
                near[k] = {nearby[k].offset, a.velocity[j], a.radius[j], j, share};
            }
            AvoidanceQuery query{a.velocity[i], preferred, maxSpeed, a.radius[i], s.comfortMargin,
                                 s.horizonSeconds, kWallHorizon, s.timeStep};
            const glm::vec2 chosen = avoidCollisions(query, std::span<const Neighbour>(near, found),
                                                     std::span<const WallPoint>(walls, wallCount), lines);
            const glm::vec2 delta = chosen - a.velocity[i];
            const float change = glm::length(delta);
            const glm::vec2 limited = change > maxDelta ? a.velocity[i] + delta * (maxDelta / change) : chosen;
            move(i, gait.walkable(limited, chosen));
        }
    });
}

void Crowd::integrate() {
    // steer() moved every agent already; the new velocities become the
    // published ones (the old ones' buffer is separation's scratch next).
    mAgents.velocity.swap(mState->nextVelocity);
}

void Crowd::arrive(uint32_t i) {
    AgentState& st = *mState;
    st.flags[i] |= kArrived;
    const uint16_t arrivals = ++st.arrivals[i];
    Random random(mAgents.id[i], arrivals);
    // Progress is measured afresh towards whatever comes next.
    st.anchor[i] = xz(mAgents.position[i]);
    st.stuckTime[i] = 0.0f;
    const uint32_t groups = uint32_t(mGoals.size());
    const GoalGroup& goal = mGoals[mAgents.goalGroup[i]];
    if (goal.onArrival == ArrivalPolicy::Wander && groups > 1) {
        const uint32_t other = random.below(groups - 1);
        mAgents.goalGroup[i] = uint16_t(other >= mAgents.goalGroup[i] ? other + 1 : other);
        return;
    }
    // Stay (or wander with nowhere else to go).
    st.flags[i] |= kStaying;
    const glm::vec2 here = xz(mAgents.position[i]);
    const glm::vec2 velocity = mAgents.velocity[i];
    const float speed = glm::length(velocity);
    pickSpot(i, speed > 1e-3f ? velocity / speed : glm::normalize(goal.region.center - here + 1e-6f), random);
}

void Crowd::pickSpot(uint32_t i, glm::vec2 inward, Random& random) {
    // A walkable spot of its own a few metres further in, so arrivals make
    // room for those behind instead of stopping in the entrance.
    AgentState& st = *mState;
    const Region& region = mGoals[mAgents.goalGroup[i]].region;
    const glm::vec2 here = xz(mAgents.position[i]);
    const glm::vec2 across(-inward.y, inward.x);
    st.spot[i] = here;
    for (int attempt = 0; attempt < 16; ++attempt) {
        const glm::vec2 spot = here + inward * random.range(2.0f, kStaySpotRange) +
                               across * random.range(-0.5f, 0.5f) * kStaySpotRange;
        if (region.contains(spot) && mNavigation->cost().passableAt(spot)) {
            st.spot[i] = spot;
            return;
        }
    }
}

void Crowd::finishStep() {
    const CrowdSettings& s = mSettings;
    AgentState& st = *mState;
    CrowdAgents& a = mAgents;
    const Navigation& nav = *mNavigation;
    core::parallelForRanges(uint32_t(a.size()), kGrain, s.threads, [&](core::IndexRange range) {
        for (uint32_t i = range.begin; i < range.end; ++i) {
            const glm::vec2 p = st.moved[i];
            // The clip follows the ground actually covered (separation's
            // pushes included), so feet stay planted.
            AgentGait::of(s, a.id[i], a.radius[i])
                .advance(s, a.velocity[i] != glm::vec2(0.0f), glm::distance(p, xz(a.position[i])), a.clip[i], a.phase[i]);
            a.position[i] = glm::vec3(p.x, mTerrain.heightAt(p.x, p.y), p.y);
            st.flags[i] &= ~kArrived;
            if (!(st.flags[i] & kStaying) && nav.field(a.goalGroup[i]).goal().contains(p)) arrive(i);
            // Stuck: wanting to walk but not getting stuckProgress away from
            // where it last was. Measured on the ground, not on the
            // potential, which rises under an agent as the crowd ahead of
            // it thickens. An agent making for its spot in a Stay goal must
            // get closer to it: one that walks round a spot others stand on
            // (it cannot creep, only walk or stand) is stuck too.
            const bool staying = st.flags[i] & kStaying;
            const float toSpot = glm::distance(p, st.spot[i]);
            const bool progress = staying ? toSpot <= glm::distance(st.anchor[i], st.spot[i]) - 0.5f * s.stuckProgress
                                          : glm::distance(p, st.anchor[i]) >= s.stuckProgress;
            if ((staying && toSpot <= kStaySpotReach) || (st.flags[i] & (kEscaping | kUnreachable)) ||
                st.fleeTime[i] > 0.0f || progress) {
                st.stuckTime[i] = 0.0f;
                st.anchor[i] = p;
            } else {
                st.stuckTime[i] += s.timeStep;
            }
        }
    });
}

void Crowd::publish() {
    const AgentState& st = *mState;
    // Counted per range in parallel (a serial pass over a million agents
    // is a few milliseconds that no number of cores shortens), then summed:
    // counts and a maximum, the same whatever the thread count.
    const uint32_t count = uint32_t(mAgents.size());
    std::vector<CrowdStats> partial((count + kStatsGrain - 1) / kStatsGrain);
    core::parallelForRanges(count, kStatsGrain, mSettings.threads, [&](core::IndexRange range) {
        CrowdStats& part = partial[range.begin / kStatsGrain];
        for (uint32_t i = range.begin; i < range.end; ++i) {
            const uint8_t flags = st.flags[i];
            part.walking += mAgents.clip[i] == AgentClip::Walk;
            part.fleeing += st.fleeTime[i] > 0.0f;
            part.escaping += (flags & kEscaping) != 0;
            part.unreachable += (flags & kUnreachable) != 0;
            part.staying += (flags & kStaying) != 0;
            part.stuck += st.stuckTime[i] > mSettings.stuckSeconds;
            part.maxStuckSeconds = std::max(part.maxStuckSeconds, st.stuckTime[i]);
            part.arrivals += (flags & kArrived) != 0;
        }
    });
    CrowdStats stats;
    stats.agents = count;
    for (const CrowdStats& part : partial) {
        stats.walking += part.walking;
        stats.fleeing += part.fleeing;
        stats.escaping += part.escaping;
        stats.unreachable += part.unreachable;
        stats.staying += part.staying;
        stats.stuck += part.stuck;
        stats.maxStuckSeconds = std::max(stats.maxStuckSeconds, part.maxStuckSeconds);
        mArrivals += part.arrivals;
    }
    stats.arrivals = mArrivals;
    stats.activeHazards = mNavigation->cost().hazardCount();
    stats.fieldTilesSolved = mStats.fieldTilesSolved;
    stats.fieldTilesWaiting = mNavigation->activeTiles();
    mStats = stats;
    mBins->build(mAgents.position, mAgents.radius, mSettings.agentHeight, mSettings.threads);
    // Now and then, agents are re-sorted in memory by the tile they stand on.
    if (mSteps % kReorderSteps == 0 && !mAgents.id.empty()) {
        reorderAgents(mAgents, *mState, mBins->order(), mSettings.threads);
        core::parallelForRanges(count, kStatsGrain, mSettings.threads, [&](core::IndexRange range) {
            for (uint32_t i = range.begin; i < range.end; ++i) mIndexOf[mAgents.id[i]] = i;
        });
        mBins->build(mAgents.position, mAgents.radius, mSettings.agentHeight, mSettings.threads);
    }
    if (mGraph && mGraph->isAlive(mNode)) mGraph->setLocalBounds(mNode, bounds());
}

} // namespace tessera::crowd
