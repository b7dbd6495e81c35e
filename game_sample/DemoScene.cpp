#include "DemoScene.h"

#include "ContentLocator.h"
#include "tessera/profiler/CpuScope.h"
#include "tessera/scene/Camera.h"
#include "tessera/terrain/HeightMapIO.h"

#include <algorithm>

namespace tessera::demo {

namespace {

// The camera flies this high above the ground at least (metres).
constexpr float kCameraClearance = 120.0f;
// Meteors aim this far ahead of the camera, so the craters form in view.
constexpr float kMeteorAimDistance = 700.0f;
constexpr double kMeteorWindowSeconds = 60.0;

} // namespace

Result<std::unique_ptr<DemoScene>> DemoScene::load(const DemoOptions& options, uint32_t frames) {
    TESSERA_CPU_SCOPE("load.terrain");
    std::filesystem::path path = options.heightmap;
    if (path.empty()) {
        auto located = locateContent(options.contentDir, "terrain/height.png");
        if (!located) return located.error();
        path = located.value();
    }
    auto field = terrain::loadHeightMapPng(path);
    if (!field) return field.error();
    std::unique_ptr<DemoScene> scene(new DemoScene());
    scene->mTerrain = std::make_unique<terrain::Terrain>(std::move(field.value()));
    terrain::Terrain& ground = *scene->mTerrain;
    for (const auto& splat : options.splats) ground.splat(splat);

    scene::CameraPathSettings pathSettings;
    pathSettings.seed = options.seed;
    pathSettings.regionMin = glm::vec2(0.0f);
    pathSettings.regionMax = ground.field().worldSize();
    pathSettings.clearance = kCameraClearance;
    scene->mPath.emplace(pathSettings, [&ground](float x, float z) { return ground.heightAt(x, z); });
    scene->mFixedPose = options.camera;
    if (options.scene == "characters") {
        auto crowd = CharacterCrowd::load(options, ground);
        if (!crowd) return crowd.error();
        scene->mCrowd = std::move(crowd.value());
    }

    if (options.meteors > 0) {
        // Spread over the run (its last frame included), or over the first
        // minute of an open-ended windowed run.
        const double duration = std::min(double(frames > 1 ? frames - 1 : 0) * kSecondsPerFrame, kMeteorWindowSeconds);
        terrain::MeteorShowerSettings shower;
        shower.count = options.meteors;
        shower.seed = options.seed;
        shower.startSeconds = 0.05 * duration;
        shower.durationSeconds = 0.9 * duration;
        shower.regionMin = pathSettings.regionMin;
        shower.regionMax = pathSettings.regionMax;
        const DemoScene& self = *scene;
        scene->mImpacts = terrain::scheduleMeteorShower(shower, [&self](double seconds) {
            scene::Camera camera;
            camera.setPose(self.cameraPose(uint32_t(seconds / kSecondsPerFrame)));
            const glm::vec3 ahead = camera.position() + camera.forward() * kMeteorAimDistance;
            return glm::vec2(ahead.x, ahead.z);
        });
    }
    return scene;
}

scene::CameraPose DemoScene::cameraPose(uint32_t frame) const {
    if (mFixedPose) return *mFixedPose;
    if (mCrowd) return mCrowd->orbitPose(double(frame) * kSecondsPerFrame);
    return mPath->sample(double(frame) * kSecondsPerFrame);
}

void DemoScene::update(uint32_t frame) {
    const double now = double(frame) * kSecondsPerFrame;
    while (mNextImpact < mImpacts.size() && mImpacts[mNextImpact].timeSeconds <= now)
        mTerrain->splat(mImpacts[mNextImpact++].splat);
}

} // namespace tessera::demo
