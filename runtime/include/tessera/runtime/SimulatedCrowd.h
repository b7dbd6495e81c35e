#pragma once
/// @file SimulatedCrowd.h
/// The crowd scene's population: thousands of agents of the crowd simulation
/// (crowd::Crowd) wandering between goals on the terrain, drawn as one
/// instanced crowd (InstancedCrowd) on a backend that draws crowds, or,
/// on one that does not, the nearest in view through the character path
/// (one draw each).

#include "tessera/runtime/CameraOrbit.h"
#include "tessera/runtime/CharacterAssets.h"
#include "tessera/runtime/CharacterPopulation.h"
#include "tessera/runtime/CharacterPoser.h"
#include "tessera/runtime/CrowdGait.h"
#include "tessera/runtime/Options.h"
#include "tessera/core/BackgroundWorker.h"
#include "tessera/core/Result.h"
#include "tessera/crowd/Crowd.h"
#include "tessera/scene/CameraPath.h"
#include "tessera/crowd/CrowdLayout.h"
#include "tessera/terrain/DrawnSurface.h"
#include "tessera/terrain/Terrain.h"

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace tessera::runtime {

class Reporter;

class SimulatedCrowd final : public CharacterPopulation {
public:
    static constexpr uint32_t kDefaultAgents = 2000;
    /// The creatures stand about this tall on average (metres): goblin-sized.
    static constexpr float kCreatureHeight = 1.4f;

    /// Loads the generated creatures, measures their walk (CrowdGait), plans
    /// the layout on `terrain` and creates the crowd of --agents agents
    /// (--threads). Errors: too many agents for the machine, a terrain
    /// without room for them (planCrowdLayout's), a creature that cannot be
    /// used. Agents walk the height field (`terrain`) and are drawn standing
    /// on `ground`, the terrain as drawn. Both must outlive the crowd.
    static Result<std::unique_ptr<SimulatedCrowd>> create(const Options& options, const terrain::Terrain& terrain,
                                                          const terrain::DrawnSurface& ground);

    /// Brings the crowd to the next frame's state, one simulation step
    /// (crowd::Crowd::step, the demo's 1/30 s, traced as "crowd.step") on:
    /// the step that ran ahead while the last frame was drawn (update()
    /// starts it once the frame's instances are built), or one now. Records
    /// the trace's crowd counters and what summary() reports.
    void step();
    /// Waits for a step running ahead. Call it before changing what a step
    /// reads (a crater on the terrain): World::update does, before its
    /// splats, so a crater reaches the crowd one step after it lands.
    void finishStepAhead() { mStepper.wait(); }
    /// Whether update() starts the next step while the frame is drawn
    /// (default true; only the instanced crowd does: its frame is drawn from
    /// the instances, not the agents).
    void setStepAhead(bool ahead) { mStepAhead = ahead; }
    /// The simulation, once any step running ahead has finished: then one
    /// step past the frame drawn.
    const crowd::Crowd& crowd() const {
        mStepper.wait();
        return *mCrowd;
    }
    const crowd::CrowdLayout& layout() const { return mLayout; }
    /// What the run showed, in one line: steps, agents walking, fleeing and
    /// stuck, arrivals, mean step time (as of the last step() call, not the
    /// step running ahead).
    std::string summary() const;
    /// How the crowd is drawn on `backend` (`gpu`: one that needs a GPU), in
    /// one line naming settings as `reporter` does.
    std::string drawingMode(const std::string& backend, bool gpu, const Reporter& reporter) const;

    CharacterAssets& assets() override { return mAssets; }
    /// Instanced (useInstancedCrowd): every agent an instance, tiers by the
    /// LOD manager. Otherwise the --crowd-draw agents nearest the camera
    /// among those in view, through the character path.
    void update(double seconds, const scene::Camera& camera, const CharacterLevels& levels) override;
    InstancedCrowd* instancedCrowd() override { return mInstanced.get(); }
    void useInstancedCrowd(bool instanced) override { mInstancedActive = instanced && mInstanced != nullptr; }
    uint32_t instanceCapacity() const override { return crowd().stats().agents; }
    /// Every agent in `region`, drawn instanced or not, as tall as it is
    /// drawn (its creature's rest height at the agent's scale); instanced,
    /// from the frame's instances, which the step running ahead leaves alone.
    void shadowCasters(const glm::vec3& region, uint32_t limit, std::vector<glm::vec4>& out) override;
    std::span<const backend::CharacterDrawItem> items() const override { return mPoser.items(); }
    /// Circling the spawn's centre (--orbit-distance, default 30 m), high
    /// enough to look over the agents.
    /// The scene's camera: a flight over the crowd (a seeded loop inside
    /// the spawn disc, low enough that the nearest agents are tessellated),
    /// or with --orbit-distance a circle around the spawn's centre.
    void dollyOrbit(float endDistance, double seconds) override {
        mOrbit.endDistance = endDistance;
        mOrbit.dollySeconds = seconds;
    }
    scene::CameraPose orbitPose(double seconds) const override;
    /// The crowd seen across, as someone at its edge would: from just
    /// outside the spawn disc on the sun's side, a few metres up (higher for
    /// a larger disc), looking at its centre, so the nearest agents are
    /// tessellated and the far side is in the far tier (the crowd
    /// benchmark's view).
    scene::CameraPose acrossPose() const;

private:
    /// Where an agent's creature can reach at any heading and pose, at the
    /// gait's stride radius: horizontally and from its feet up (metres).
    struct Reach {
        float radius = 0.0f, bottom = 0.0f, top = 0.0f;
    };

    SimulatedCrowd() = default;
    /// The crowd's settings for the gait (stride, idle cycle, flow speed) and
    /// boxes tall enough for the tallest creature; fills mReach.
    crowd::CrowdSettings settings(uint32_t threads);
    /// Radii around the gait's stride radius, speeds around its natural speed.
    crowd::SpawnPattern spawnPattern(uint32_t seed) const;
    /// Where an agent at `position` (on the height field) is drawn standing:
    /// its (x, z) on the drawn ground.
    glm::vec3 standing(const glm::vec3& position) const;
    /// The creature agent `agent` is drawn as: its kind of walker
    /// (CrowdGait::apply gives the crowd one kind per creature, in order).
    uint32_t creatureOf(uint32_t agent) const;
    /// The draw scale of agent `agent` as creature `creature`.
    float agentScale(uint32_t agent, uint32_t creature) const;
    glm::mat4 agentWorld(uint32_t agent, uint32_t creature) const;
    /// Every agent as an instance of the instanced crowd, then the next step
    /// started ahead (mStepAhead) and the LOD selection beside it.
    void updateInstances(const scene::Camera& camera, const CharacterLevels& levels);
    /// One step of the simulation, its time added to mStepMs; on the calling
    /// thread or mStepper's.
    void runStep();

    const terrain::Terrain* mTerrain = nullptr;
    const terrain::DrawnSurface* mGround = nullptr;
    CharacterAssets mAssets;
    CharacterPoser mPoser;
    CrowdGait mGait;
    std::vector<Reach> mReach;
    std::vector<float> mRestHeights; ///< per creature: its rest-pose height (CreatureGait::height)
    crowd::CrowdLayout mLayout;
    std::unique_ptr<crowd::Crowd> mCrowd;
    std::unique_ptr<InstancedCrowd> mInstanced;
    bool mInstancedActive = false;
    CameraOrbit mOrbit;
    std::optional<scene::CameraPath> mFlight; ///< unless --orbit-distance
    uint32_t mDrawCount = 0;
    double mStepMs = 0.0; ///< summed over every step, by runStep
    /// What step() last brought the frame to (summary() reports it).
    struct Shown {
        crowd::CrowdStats stats;
        uint64_t steps = 0;
        double seconds = 0.0, stepMs = 0.0;
    } mShown;
    bool mStepAhead = true;
    bool mAhead = false; ///< a step was started on mStepper and step() has not taken it
    /// Last member: destroyed first, so a step in flight ends before the
    /// crowd it steps goes.
    mutable core::BackgroundWorker mStepper;
    std::vector<uint32_t> mCulled;
    std::vector<std::pair<float, uint32_t>> mNearest; ///< squared distance, agent
};

} // namespace tessera::runtime
