#include "tessera/crowd/Crowd.h"

#include "AgentBins.h"
#include "AgentState.h"
#include "CrowdChecks.h"
#include "Navigation.h"
#include "NeighbourGrid.h"
#include "tessera/profiler/CpuScope.h"
#include "tessera/scene/SceneGraph.h"

#include <algorithm>
#include <cmath>

namespace tessera::crowd {

Crowd::Crowd(const terrain::Terrain& terrain, const CrowdSettings& settings, std::span<const GoalGroup> goals)
    : mTerrain(terrain), mSettings(settings), mGoals(goals.begin(), goals.end()), mState(std::make_unique<AgentState>()),
      mNavigation(std::make_unique<Navigation>(terrain, settings, goals)),
      mBins(std::make_unique<AgentBins>(mNavigation->grid())), mNeighbours(std::make_unique<NeighbourGrid>()),
      mSplatsSeen(terrain.splatHistory().size()) {}

Crowd::~Crowd() { detach(); }

Result<std::unique_ptr<Crowd>> Crowd::create(const terrain::Terrain& terrain, const CrowdSettings& settings,
                                             std::span<const GoalGroup> goals, std::span<const SpawnPattern> spawns) {
    TESSERA_CPU_SCOPE("crowd.create");
    if (Status ok = checkSettings(settings, terrain); !ok) return ok.error();
    if (Status ok = checkGoals(goals); !ok) return ok.error();
    uint64_t total = 0;
    for (const SpawnPattern& spawn : spawns) total += spawn.count;
    if (total > kMaxAgents)
        return fail("crowd: ", std::to_string(total), " agents asked for; one crowd holds at most ",
                    std::to_string(kMaxAgents));
    std::unique_ptr<Crowd> crowd(new Crowd(terrain, settings, goals));
    for (size_t g = 0; g < goals.size(); ++g)
        if (Status ok = checkWalkable(crowd->navGrid(), goals[g].region, goalName(goals, g)); !ok)
            return ok.error();
    // Fields first, so agents are placed only where they have a route; then
    // the crowd's own density, settled before the first step.
    crowd->mNavigation->solveAll();
    if (Status ok = crowd->spawn(spawns); !ok) return ok.error();
    crowd->publish();
    crowd->splatDensity();
    crowd->mNavigation->settle();
    crowd->publish();
    return crowd;
}

CrowdMemory Crowd::estimateMemory(const terrain::Terrain& terrain, const CrowdSettings& settings, uint64_t agents,
                                  uint32_t groups) {
    // Published arrays, private state, neighbour grid and bins, as the sizes
    // of their element types say (at most about one grid cell per agent, and
    // two marks per cell for separation).
    constexpr size_t kAgentBytes = sizeof(glm::vec3) + sizeof(glm::vec2) + 3 * sizeof(float) + sizeof(uint16_t) +
                                   sizeof(AgentClip) + sizeof(float) + sizeof(uint32_t) +            // published
                                   4 * sizeof(glm::vec2) + 2 * sizeof(float) + sizeof(uint16_t) + sizeof(uint8_t) + // state
                                   2 * sizeof(uint32_t) + sizeof(glm::vec2) + 2 * sizeof(uint8_t) +  // grid, marks
                                   2 * sizeof(uint32_t) + sizeof(uint32_t);                          // bins, indexOf
    const glm::vec2 size = terrain.field().worldSize();
    const double cells = std::floor(double(size.x) / settings.cellSize) * std::floor(double(size.y) / settings.cellSize);
    CrowdMemory memory;
    memory.agentBytes = size_t(agents) * kAgentBytes;
    memory.fieldBytes = size_t(cells * (2 * sizeof(float) + sizeof(uint16_t) + groups * (sizeof(float) + 1)));
    memory.bytesPerAgent = double(kAgentBytes);
    return memory;
}

const NavGrid& Crowd::navGrid() const { return mNavigation->grid(); }
const PotentialField& Crowd::field(uint32_t group) const { return mNavigation->field(group); }
bool Crowd::passable(glm::vec2 p) const { return mNavigation->cost().passableAt(p); }
const scene::Aabb& Crowd::bounds() const { return mBins->bounds(); }
void Crowd::cull(const scene::Frustum& frustum, std::vector<uint32_t>& out) const { mBins->cull(frustum, out); }

CrowdMemory Crowd::memory() const {
    const CrowdAgents& a = mAgents;
    CrowdMemory memory;
    memory.agentBytes = a.position.capacity() * sizeof(glm::vec3) + a.velocity.capacity() * sizeof(glm::vec2) +
                        (a.heading.capacity() + a.radius.capacity() + a.preferredSpeed.capacity() +
                         a.phase.capacity()) * sizeof(float) +
                        a.goalGroup.capacity() * sizeof(uint16_t) + a.clip.capacity() * sizeof(AgentClip) +
                        (a.id.capacity() + mIndexOf.capacity()) * sizeof(uint32_t) + mState->bytes() + mNeighbours->agentBytes() + mBins->agentBytes();
    memory.fieldBytes = mNavigation->bytes() + mBins->tileBytes() + mNeighbours->tileBytes();
    memory.bytesPerAgent = a.size() ? double(memory.agentBytes) / double(a.size()) : 0.0;
    return memory;
}

OverlapReport Crowd::measureOverlap() const {
    OverlapReport report;
    const auto& pos = mAgents.position;
    const uint32_t n = uint32_t(pos.size());
    float largest = 0.0f;
    for (float r : mAgents.radius) largest = std::max(largest, r);
    NeighbourGrid grid;
    grid.build(pos, tileAgents(), std::max(2.0f * largest, 0.5f), mSettings.threads);
    std::vector<uint8_t> involved(n, 0);
    for (uint32_t i = 0; i < n; ++i) {
        const glm::vec2 p(pos[i].x, pos[i].z);
        grid.forEachNear(p, mAgents.radius[i] + largest, [&](uint32_t j, glm::vec2 q) {
            if (j <= i) return;
            const float reach = mAgents.radius[i] + mAgents.radius[j];
            const float overlap = (reach - glm::distance(p, q)) / reach;
            report.worst = std::max(report.worst, overlap);
            if (overlap > 0.05f) ++report.pairs, involved[i] = involved[j] = 1;
        });
    }
    for (uint8_t flag : involved) report.overlapping += flag;
    return report;
}

scene::NodeId Crowd::attach(scene::SceneGraph& graph, scene::NodeId parent, uint32_t kind) {
    detach();
    mGraph = &graph;
    mNode = graph.createNode("crowd", parent);
    graph.setTag(mNode, kind, 0);
    graph.setLocalBounds(mNode, bounds());
    return mNode;
}

void Crowd::detach() {
    if (mGraph && mGraph->isAlive(mNode)) mGraph->destroyNode(mNode);
    mGraph = nullptr;
    mNode = {};
}

} // namespace tessera::crowd
