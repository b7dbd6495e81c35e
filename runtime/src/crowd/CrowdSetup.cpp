#include "crowd/CrowdSetup.h"

#include "crowd/SystemInfo.h"
#include "tessera/runtime/Settings.h"
#include "tessera/profiler/CpuScope.h"

#include <algorithm>
#include <chrono>
#include <cstdio>

#include <glm/geometric.hpp>

namespace tessera::runtime {
namespace {

/// The share of the available memory a crowd may take.
constexpr double kMemoryShare = 0.75;

std::string mib(double bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.0f MiB", bytes / (1024.0 * 1024.0));
    return text;
}

} // namespace

Status checkCrowdFits(const terrain::Terrain& terrain, const crowd::CrowdSettings& settings, uint64_t agents) {
    const uint64_t available = availableMemoryBytes();
    if (available == 0) return {}; // unknown: let the allocation decide
    const crowd::CrowdMemory need = crowd::Crowd::estimateMemory(terrain, settings, agents, kCrowdGoalGroups);
    const double budget = kMemoryShare * double(available);
    const double total = double(need.agentBytes) + double(need.fieldBytes);
    if (total <= budget) return {};
    const double fit = std::max(0.0, (budget - double(need.fieldBytes)) / std::max(need.bytesPerAgent, 1.0));
    return failSetting(setting::kAgents, " ", std::to_string(agents), ": the crowd needs about ", mib(total), " and this machine has ",
                mib(double(available)), " available (a crowd may take ", std::to_string(int(kMemoryShare * 100)),
                "%); about ", std::to_string(uint64_t(fit)), " agents would fit");
}

Result<PlannedCrowd> planCrowd(const terrain::Terrain& terrain, const crowd::CrowdSettings& settings, uint32_t agents,
                               const crowd::SpawnPattern& pattern) {
    if (Status fits = checkCrowdFits(terrain, settings, agents); !fits) return fits.error();
    PlannedCrowd planned;
    {
        TESSERA_CPU_SCOPE("crowd.layout");
        const crowd::NavGrid grid(terrain, settings.cellSize, settings.maxSlopeDegrees, settings.slopeSpeedAtLimit);
        crowd::CrowdLayoutRequest request;
        request.agents = agents;
        request.groups = kCrowdGoalGroups;
        request.agentRadius = pattern.radiusMax;
        request.goalDistance = kCrowdGoalDistance;
        request.onArrival = crowd::ArrivalPolicy::Wander;
        auto layout = crowd::planCrowdLayout(grid, request);
        if (!layout) return layout.error();
        planned.layout = std::move(layout.value());
    }
    crowd::SpawnPattern spawn = pattern;
    spawn.region = planned.layout.spawn;
    spawn.count = agents;
    spawn.goalGroup = crowd::SpawnPattern::kEveryGroup;
    const auto start = std::chrono::steady_clock::now();
    auto created = crowd::Crowd::create(terrain, settings, planned.layout.goals, {&spawn, 1});
    if (!created) return created.error();
    planned.createMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    planned.crowd = std::move(created.value());
    return planned;
}

std::string describeLayout(const crowd::CrowdLayout& layout) {
    // The goals lie on the most open ground near their ideal spots, so their
    // distances vary a little around kCrowdGoalDistance.
    float nearest = 0.0f, farthest = 0.0f;
    for (size_t g = 0; g < layout.goals.size(); ++g) {
        const float d = glm::distance(layout.goals[g].region.center, layout.spawn.center);
        nearest = g ? std::min(nearest, d) : d;
        farthest = g ? std::max(farthest, d) : d;
    }
    char text[160];
    std::snprintf(text, sizeof text, "a %.0f m spawn disc at (%.0f, %.0f) with %zu goals %.0f to %.0f m away",
                  double(layout.spawn.halfSize.x), double(layout.spawn.center.x), double(layout.spawn.center.y),
                  layout.goals.size(), double(nearest), double(farthest));
    return text;
}

} // namespace tessera::runtime
