#include "tessera/runtime/World.h"

#include "characters/CharacterCrowd.h"
#include "world/ContentLocator.h"
#include "tessera/profiler/CpuScope.h"
#include "tessera/scene/Camera.h"
#include "tessera/terrain/HeightMapIO.h"

#include <algorithm>

namespace tessera::runtime {

namespace {

// The camera flies this high above the ground at least (metres).
constexpr float kCameraClearance = 120.0f;
// Meteors aim this far ahead of the camera, so the craters form in view.
constexpr float kMeteorAimDistance = 700.0f;
constexpr double kMeteorWindowSeconds = 60.0;

} // namespace

Result<terrain::HeightField> loadDemoHeightField(const Options& options) {
    std::filesystem::path path = options.heightmap;
    if (path.empty()) {
        auto located = locateContent(options.contentDir, "terrain/height.png");
        if (!located) return located.error();
        path = located.value();
    }
    return terrain::loadHeightMapPng(path);
}

Result<std::unique_ptr<World>> World::load(const Options& options, uint32_t frames) {
    std::unique_ptr<World> scene(new World());
    {
        TESSERA_CPU_SCOPE("load.terrain");
        auto field = loadDemoHeightField(options);
        if (!field) return field.error();
        scene->mTerrain = std::make_unique<terrain::Terrain>(std::move(field.value()));
    }
    terrain::Terrain& ground = *scene->mTerrain;
    for (const auto& splat : options.splats) ground.splat(splat);
    scene->mGround = std::make_unique<terrain::DrawnSurface>(ground);

    scene::CameraPathSettings pathSettings;
    pathSettings.seed = options.seed;
    pathSettings.regionMin = glm::vec2(0.0f);
    pathSettings.regionMax = ground.field().worldSize();
    pathSettings.clearance = kCameraClearance;
    scene->mPath.emplace(pathSettings, [&ground](float x, float z) { return ground.heightAt(x, z); });
    scene->mFixedPose = options.camera;
    if (options.scene == "characters") {
        // --character-surface catmull-clark: the --model characters stand
        // only as Catmull-Clark surfaces, so the crowd leaves them out.
        Options crowdOptions = options;
        if (options.characterSurface == "catmull-clark") crowdOptions.models.clear();
        auto crowd = CharacterCrowd::load(crowdOptions, ground, *scene->mGround);
        if (!crowd) return crowd.error();
        if (options.characterSurface != "planar") {
            auto characters = SubdivCharacters::load(options, ground, crowd.value()->site());
            if (!characters) return characters.error();
            scene->mSubdivCharacters = std::move(characters.value());
            crowd.value()->frameAlso(scene->mSubdivCharacters->bounds());
        }
        if (!options.surfaces.empty()) {
            // The surfaces stand at the middle of the creatures' circles;
            // with creatures there too, 3 m further on as the camera starts,
            // so they stand behind them rather than in them.
            const glm::vec3 site = crowd.value()->site();
            glm::vec2 at(site.x, site.z);
            if (options.crowd > 0 || !options.models.empty()) {
                const glm::vec3 eye = crowd.value()->orbitPose(0.0).position;
                const glm::vec2 away = glm::vec2(site.x - eye.x, site.z - eye.z);
                if (glm::length(away) > 1e-3f) at += 3.0f * glm::normalize(away);
            }
            auto surfaces = SubdivModels::load(options, ground, at);
            if (!surfaces) return surfaces.error();
            scene->mSurfaces = std::move(surfaces.value());
            if (options.subdiv.levelEnd)
                scene->mSurfaces->sweepLevel(*options.subdiv.levelEnd,
                                             double(frames > 1 ? frames - 1 : 1) * kSecondsPerFrame);
            crowd.value()->frameAlso(scene->mSurfaces->bounds());
        }
        scene->mCharacters = std::move(crowd.value());
    } else if (options.scene == "crowd") {
        auto crowd = SimulatedCrowd::create(options, ground, *scene->mGround);
        if (!crowd) return crowd.error();
        scene->mSimulated = crowd.value().get();
        scene->mCharacters = std::move(crowd.value());
    }
    if (options.orbitDistanceEnd && scene->mCharacters)
        scene->mCharacters->dollyOrbit(*options.orbitDistanceEnd, double(frames > 1 ? frames - 1 : 1) * kSecondsPerFrame);
    if (options.meteors > 0) scene->scheduleMeteors(options, frames);
    return scene;
}

void World::scheduleMeteors(const Options& options, uint32_t frames) {
    // Spread over the run (its last frame included), or over the first
    // minute of an open-ended windowed run.
    const double duration = std::min(double(frames > 1 ? frames - 1 : 0) * kSecondsPerFrame, kMeteorWindowSeconds);
    terrain::MeteorShowerSettings shower;
    shower.count = options.meteors;
    shower.seed = options.seed;
    shower.startSeconds = 0.05 * duration;
    shower.durationSeconds = 0.9 * duration;
    shower.regionMax = mTerrain->field().worldSize();
    if (mSimulated) {
        // Among the agents: anywhere on the spawn disc, where they start.
        const crowd::Region& spawn = mSimulated->layout().spawn;
        shower.scatter = spawn.halfSize.x;
        mImpacts = terrain::scheduleMeteorShower(shower, [&spawn](double) { return spawn.center; });
        return;
    }
    mImpacts = terrain::scheduleMeteorShower(shower, [this](double seconds) {
        scene::Camera camera;
        camera.setPose(cameraPose(uint32_t(seconds / kSecondsPerFrame)));
        const glm::vec3 ahead = camera.position() + camera.forward() * kMeteorAimDistance;
        return glm::vec2(ahead.x, ahead.z);
    });
}

scene::CameraPose World::cameraPose(uint32_t frame) const {
    if (mFixedPose) return *mFixedPose;
    if (mCharacters) return mCharacters->orbitPose(double(frame) * kSecondsPerFrame);
    return mPath->sample(double(frame) * kSecondsPerFrame);
}

void World::update(uint32_t frame) {
    const double now = double(frame) * kSecondsPerFrame;
    // A step running ahead reads the terrain: it ends before a crater lands.
    if (mSimulated) mSimulated->finishStepAhead();
    while (mNextImpact < mImpacts.size() && mImpacts[mNextImpact].timeSeconds <= now)
        mTerrain->splat(mImpacts[mNextImpact++].splat);
    if (mSimulated) mSimulated->step();
}

void World::dropMeteor(const terrain::CraterSplat& splat) {
    if (mSimulated) mSimulated->finishStepAhead();
    mTerrain->splat(splat);
}

} // namespace tessera::runtime
