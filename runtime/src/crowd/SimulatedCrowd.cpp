#include "tessera/runtime/SimulatedCrowd.h"

#include "world/ShadowCasters.h"

#include "tessera/shaders/CrowdInstance.h"
#include "crowd/CrowdSetup.h"
#include "tessera/runtime/Reporter.h"
#include "tessera/runtime/Settings.h"
#include "tessera/core/Log.h"
#include "tessera/core/ParallelFor.h"
#include "tessera/profiler/CpuScope.h"
#include "tessera/profiler/Profiler.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtx/norm.hpp>

namespace tessera::runtime {
namespace {

constexpr float kStrideRadius = 0.4f;   // agent radius the gait is measured at (metres)
constexpr float kRadiusSpread = 0.05f;  // agent radii within +-5% of it
constexpr float kSpeedSpread = 0.1f;    // preferred speeds within +-10% of the natural speed
constexpr float kOrbitDistance = 30.0f; // metres, unless --orbit-distance
// Camera height per metre of orbit distance. At 30 m out the view looks 42
// degrees down and the nearest agents in view stand about 28 m away, where
// CharacterPoser's level is about 1: each drawn creature stays near its
// 5,000 cage triangles (a level just above 1 makes 13 of each), which keeps
// lavapipe frames with 48 creatures well under a second.
constexpr float kOrbitRise = 0.9f;
constexpr float kOrbitMinHeight = 4.0f; // at least this high, to see over the agents
constexpr float kOrbitClearance = 0.5f; // over ground rising under it: this share of the height
// acrossPose: metres outside the spawn disc, and the height: a person's
// eye level plus a rise with the disc's size, so a large crowd's far side
// stays in view over the near agents.
constexpr float kAcrossMargin = 4.0f;
// The flight over the crowd: metres above the ground and per second.
constexpr float kFlightClearance = 9.0f;
constexpr float kFlightSpeed = 6.0f;
constexpr float kAcrossHeight = 2.5f;
constexpr float kAcrossRise = 0.08f;
constexpr float kLookHeight = 0.7f; // the camera aims this high above the spawn's centre

std::string describeGait(const CrowdGait& gait, const CharacterAssets& assets) {
    char text[200];
    std::snprintf(text, sizeof text, "crowd gait at radius %.2f m (mean %.2f m per walk cycle, %.2f m/s):",
                  double(gait.strideRadius), double(gait.walkStrideLength), double(gait.naturalSpeed));
    std::string line = text;
    for (size_t i = 0; i < gait.creatures.size(); ++i) {
        const CreatureGait& c = gait.creatures[i];
        std::snprintf(text, sizeof text, " %s %.2f units drawn x%.3g (%.2f m), %.2f m per %.2f s cycle",
                      std::filesystem::path(assets[i].file).filename().c_str(), double(c.height), double(c.scale),
                      double(c.height * c.scale), double(gait.strideMetres(i)), double(c.walkCycleSeconds));
        line += text;
    }
    return line;
}

} // namespace

Result<std::unique_ptr<SimulatedCrowd>> SimulatedCrowd::create(const Options& options, const terrain::Terrain& terrain,
                                                               const terrain::DrawnSurface& ground) {
    std::unique_ptr<SimulatedCrowd> self(new SimulatedCrowd());
    self->mTerrain = &terrain;
    self->mGround = &ground;
    self->mDrawCount = options.crowdDraw;
    const uint32_t agents = options.agents.empty() ? kDefaultAgents : options.agents.front();
    if (Status ok = self->mAssets.addFroblins(options.contentDir, CharacterAssets::kFroblinSeeds); !ok)
        return ok.error();
    // --model files join the generated creatures in the crowd: each must
    // walk, so it needs a skin and a clip (the gait check below then needs
    // the clip to cover ground).
    if (CharacterAssets::kFroblinSeeds + options.models.size() > TS_CROWD_MAX_CHARACTERS)
        return failSetting(setting::kModels, ": a crowd mixes at most ", std::to_string(TS_CROWD_MAX_CHARACTERS),
                           " creatures, ", std::to_string(CharacterAssets::kFroblinSeeds), " generated and ",
                           std::to_string(options.models.size()), " models given");
    for (const std::string& file : options.models) {
        if (Status ok = self->mAssets.add(file); !ok) return ok.error();
        const character::CharacterAsset& asset = self->mAssets.all().back().asset;
        if (asset.cage.bindings.empty())
            return fail(file, ": has no skin, so it cannot walk in the crowd (a crowd's creatures are skinned glTF "
                              "meshes with an animation clip)");
        if (asset.clips.empty())
            return fail(file, ": has no animation clip, so it cannot walk in the crowd (it needs a walk cycle)");
    }
    auto gait = measureCrowdGait(self->mAssets, kCreatureHeight, kStrideRadius);
    if (!gait) return gait.error();
    self->mGait = std::move(gait.value());
    for (const CreatureGait& c : self->mGait.creatures) self->mRestHeights.push_back(c.height);
    log::info(describeGait(self->mGait, self->mAssets));

    auto instanced = InstancedCrowd::create(self->mAssets);
    if (!instanced) return instanced.error();
    self->mInstanced = std::move(instanced.value());

    auto planned = planCrowd(terrain, self->settings(options.threads), agents, self->spawnPattern(options.seed));
    if (!planned) return planned.error();
    self->mLayout = std::move(planned.value().layout);
    self->mCrowd = std::move(planned.value().crowd);
    log::info("crowd created in " + std::to_string(std::lround(planned.value().createMs)) + " ms");

    const float distance = options.orbitDistance.value_or(kOrbitDistance);
    const glm::vec2 centre = self->mLayout.spawn.center;
    const float height = std::max(kOrbitMinHeight, kOrbitRise * distance);
    self->mOrbit = {{centre.x, terrain.heightAt(centre.x, centre.y), centre.y},
                    distance,
                    height,
                    kLookHeight,
                    kOrbitClearance * height};
    if (!options.orbitDistance) {
        // A loop inside the spawn disc (CameraPath keeps its control points
        // within 80% of the region's half-size), low and slow: the agents
        // ahead and below fill the view, the nearest tessellated.
        scene::CameraPathSettings flight;
        flight.seed = options.seed;
        flight.regionMin = centre - glm::vec2(self->mLayout.spawn.halfSize.x);
        flight.regionMax = centre + glm::vec2(self->mLayout.spawn.halfSize.x);
        flight.clearance = kFlightClearance;
        flight.speed = kFlightSpeed;
        self->mFlight.emplace(flight, [&terrain](float x, float z) { return terrain.heightAt(x, z); });
    }
    std::printf("crowd: %u agents on %s\n", agents, describeLayout(self->mLayout).c_str());
    std::fflush(stdout);
    return self;
}

scene::CameraPose SimulatedCrowd::orbitPose(double seconds) const {
    return mFlight ? mFlight->sample(seconds) : mOrbit.pose(*mTerrain, seconds);
}

scene::CameraPose SimulatedCrowd::acrossPose() const {
    const float radius = mLayout.spawn.halfSize.x;
    CameraOrbit across = mOrbit;
    across.distance = radius + kAcrossMargin;
    across.height = kAcrossHeight + kAcrossRise * radius;
    across.lookHeight = 0.0f;
    across.clearance = kOrbitClearance * across.height;
    return across.pose(*mTerrain, 0.0);
}

crowd::CrowdSettings SimulatedCrowd::settings(uint32_t threads) {
    crowd::CrowdSettings settings;
    settings.threads = threads;
    mGait.apply(settings);
    // A stream walking at the creatures' own pace is a free walk.
    settings.flowSpeed = mGait.naturalSpeed;
    settings.agentHeight = 0.0f;
    mReach.clear();
    for (size_t i = 0; i < mAssets.size(); ++i) {
        const scene::Aabb& box = mAssets[i].box;
        const float scale = mGait.creatures[i].scale;
        const glm::vec2 far =
            glm::max(glm::abs(glm::vec2(box.min.x, box.min.z)), glm::abs(glm::vec2(box.max.x, box.max.z)));
        mReach.push_back({glm::length(far) * scale, box.min.y * scale, box.max.y * scale});
        settings.agentHeight = std::max(settings.agentHeight, box.max.y * scale * (1.0f + kRadiusSpread));
    }
    return settings;
}

crowd::SpawnPattern SimulatedCrowd::spawnPattern(uint32_t seed) const {
    crowd::SpawnPattern pattern;
    pattern.seed = seed;
    pattern.radiusMin = mGait.strideRadius * (1.0f - kRadiusSpread);
    pattern.radiusMax = mGait.strideRadius * (1.0f + kRadiusSpread);
    pattern.speedMin = mGait.naturalSpeed * (1.0f - kSpeedSpread);
    pattern.speedMax = mGait.naturalSpeed * (1.0f + kSpeedSpread);
    return pattern;
}

std::string SimulatedCrowd::drawingMode(const std::string& backend, bool gpu, const Reporter& reporter) const {
    if (mInstancedActive)
        return "crowd: every agent drawn instanced, culled and sorted into LOD tiers " +
               std::string(gpu ? "on the GPU by " : "on the CPU by ") + backend;
    return mDrawCount ? "crowd: the " + std::to_string(mDrawCount) +
                            " nearest in view drawn with the character path (" + backend + " draws no instanced crowds)"
                      : "crowd: none drawn (" + reporter.name(setting::kAgentsDrawn) + " 0)";
}

void SimulatedCrowd::runStep() {
    {
        TESSERA_CPU_SCOPE("crowd.step");
        mCrowd->step();
    }
    mStepMs += mCrowd->lastTimings().total();
}

void SimulatedCrowd::step() {
    if (mAhead) {
        mStepper.wait();
        mAhead = false;
    } else {
        runStep();
    }
    const crowd::CrowdStats& s = mCrowd->stats();
    mShown = {s, mCrowd->stepCount(), mCrowd->time(), mStepMs};
    auto& profiler = profiler::Profiler::global();
    const uint64_t frame = profiler.currentFrame(), now = profiler.nowNs();
    profiler.recordCounter({"crowd agents", frame, now, double(s.agents)});
    profiler.recordCounter({"crowd walking", frame, now, double(s.walking)});
    profiler.recordCounter({"crowd fleeing", frame, now, double(s.fleeing)});
    profiler.recordCounter({"crowd field tiles solved", frame, now, double(s.fieldTilesSolved)});
}

std::string SimulatedCrowd::summary() const {
    const crowd::CrowdStats& s = mShown.stats;
    const uint64_t steps = mShown.steps;
    char text[256];
    std::snprintf(text, sizeof text,
                  "crowd: %llu steps (%.1f s), %u agents: %u walking, %u fleeing, %u stuck, %llu arrivals; a step "
                  "took %.2f ms on average",
                  static_cast<unsigned long long>(steps), mShown.seconds, s.agents, s.walking, s.fleeing, s.stuck,
                  static_cast<unsigned long long>(s.arrivals), steps ? mShown.stepMs / double(steps) : 0.0);
    return text;
}

glm::vec3 SimulatedCrowd::standing(const glm::vec3& position) const {
    // The simulation walks the height field; the creature is drawn on the
    // ground the backend draws, which at a low level lies metres above a
    // hollow or below a crest (terrain::DrawnSurface).
    return {position.x, mGround->heightAt(position.x, position.z), position.z};
}

uint32_t SimulatedCrowd::creatureOf(uint32_t agent) const {
    return mCrowd->settings().kindIndex(mCrowd->agents().id[agent]);
}

float SimulatedCrowd::agentScale(uint32_t agent, uint32_t creature) const {
    // An agent's stride grows with its radius (CrowdSettings::strideRadius),
    // so its creature does too.
    return mGait.creatures[creature].scale * mCrowd->agents().radius[agent] / mGait.strideRadius;
}

glm::mat4 SimulatedCrowd::agentWorld(uint32_t agent, uint32_t creature) const {
    const crowd::CrowdAgents& agents = mCrowd->agents();
    const float scale = agentScale(agent, creature);
    glm::mat4 world = glm::translate(glm::mat4(1.0f), standing(agents.position[agent]));
    world = glm::rotate(world, agents.heading[agent], glm::vec3(0, 1, 0));
    return glm::scale(world, glm::vec3(scale));
}

void SimulatedCrowd::updateInstances(const scene::Camera& camera, const CharacterLevels& levels) {
    const crowd::CrowdAgents& agents = mCrowd->agents();
    const uint32_t count = uint32_t(agents.id.size());
    mInstanced->begin(count);
    // Independent per agent: spread over the cores (65,000 agents a frame).
    core::parallelForRanges(count, 4096, mCrowd->settings().threads, [&](core::IndexRange range) {
        for (uint32_t i = range.begin; i < range.end; ++i) {
            const uint32_t creature = creatureOf(i);
            const CreatureGait& gait = mGait.creatures[creature];
            const scene::Aabb& box = mAssets[creature].box;
            const float scale = agentScale(i, creature);
            const glm::vec3 p = standing(agents.position[i]);
            const glm::vec3 centre = box.center();
            shader::CrowdInstance instance;
            // A sphere holding the box at any heading: the box's, grown by how
            // far its centre sits off the vertical axis.
            instance.sphere =
                glm::vec4(p + glm::vec3(0.0f, scale * centre.y, 0.0f),
                          scale * (glm::length(box.extents()) + glm::length(glm::vec2(centre.x, centre.z))));
            instance.placement = glm::vec4(p, agents.heading[i]);
            instance.animation = glm::vec4(agents.phase[i], scale, 0.0f, 0.0f);
            const int clip = agents.clip[i] == crowd::AgentClip::Walk ? gait.walkClip : gait.idleClip;
            // Variety, as the Froblins had: every agent its own shade.
            const uint32_t h = agents.id[i] * 2654435761u;
            const uint32_t tint = (215u + ((h >> 8) & 31u)) | ((215u + ((h >> 16) & 31u)) << 8) |
                                  ((215u + ((h >> 24) & 31u)) << 16) | (255u << 24);
            instance.ids = glm::uvec4(agents.id[i], creature, mInstanced->bakedClip(creature, clip), tint);
            mInstanced->set(i, instance);
        }
    });
    // The frame is drawn from the instances from here on: the next step
    // runs beside the LOD selection and the drawing (it reads the terrain,
    // as the selection's horizon does; nothing here writes it).
    if (mStepAhead) {
        mAhead = true;
        mStepper.run([this] { runStep(); });
    }
    lod::LodPolicy policy = levels.lod;
    policy.fixedLevel = levels.fixedLevel.value_or(0.0f);
    mInstanced->setHorizon(*mTerrain);
    mInstanced->select(lod::LodView::fromCamera(camera, levels.viewportHeight, levels.maxLevel), policy);
}

void SimulatedCrowd::update(double, const scene::Camera& camera, const CharacterLevels& levels) {
    TESSERA_CPU_SCOPE("crowd.draw");
    mPoser.begin(camera, levels);
    if (mInstancedActive) {
        mPoser.finish(mAssets);
        return updateInstances(camera, levels);
    }
    if (mDrawCount == 0) return mPoser.finish(mAssets);
    const scene::Frustum frustum = camera.frustum();
    const crowd::CrowdAgents& agents = mCrowd->agents();
    const glm::vec3 eye = camera.position();
    // The crowd culls by tiles; each candidate's creature is then tested on
    // its own, with a box that holds it at any heading, so only agents really
    // in view compete for the drawn slots.
    mCulled.clear();
    mCrowd->cull(frustum, mCulled);
    mNearest.clear();
    for (uint32_t i : mCulled) {
        const Reach& reach = mReach[creatureOf(i)];
        const float size = agents.radius[i] / mGait.strideRadius;
        const glm::vec3 p = standing(agents.position[i]);
        const scene::Aabb box{p + size * glm::vec3(-reach.radius, reach.bottom, -reach.radius),
                              p + size * glm::vec3(reach.radius, reach.top, reach.radius)};
        if (frustum.intersects(box)) mNearest.emplace_back(glm::distance2(p, eye), i);
    }
    // Nearest first (ties by index, so the choice is deterministic).
    const size_t drawn = std::min<size_t>(mDrawCount, mNearest.size());
    std::partial_sort(mNearest.begin(), mNearest.begin() + ptrdiff_t(drawn), mNearest.end());
    for (size_t k = 0; k < drawn; ++k) {
        const uint32_t i = mNearest[k].second;
        const uint32_t creature = creatureOf(i);
        const CreatureGait& gait = mGait.creatures[creature];
        const int clip = agents.clip[i] == crowd::AgentClip::Walk ? gait.walkClip : gait.idleClip;
        const float duration = clip >= 0 ? mAssets[creature].asset.clips[size_t(clip)].duration() : 0.0f;
        mPoser.offer(agents.id[i], creature, agentWorld(i, creature), clip, agents.phase[i] * duration);
    }
    mPoser.finish(mAssets);
}

void SimulatedCrowd::shadowCasters(const glm::vec3& region, uint32_t limit, std::vector<glm::vec4>& out) {
    out.clear();
    if (mInstancedActive) {
        // From the frame's instances: the agents may be a step further on.
        mInstanced->shadowCasters(mRestHeights, region, out);
        return keepNearest(region, limit, out);
    }
    const crowd::CrowdAgents& agents = crowd().agents();
    for (uint32_t i = 0; i < agents.position.size(); ++i) {
        const glm::vec3& p = agents.position[i];
        if (!insideRegion(region, p)) continue;
        // As tall as it is drawn: a creature of another build mixed in
        // (--model) casts its own size, not the crowd's mean.
        const uint32_t creature = creatureOf(i);
        out.emplace_back(p, mGait.creatures[creature].height * agentScale(i, creature));
    }
    keepNearest(region, limit, out);
}

} // namespace tessera::runtime
