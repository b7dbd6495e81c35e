#pragma once
/// @file DemoScene.h
/// The demo's world: the terrain (CPU copy and derived data), the scripted
/// camera flight over it, the meteor shower that deforms it and, in the
/// characters scene, the crowd walking on it.

#include "CharacterCrowd.h"
#include "DemoOptions.h"
#include "tessera/core/Result.h"
#include "tessera/scene/CameraPath.h"
#include "tessera/terrain/MeteorShower.h"
#include "tessera/terrain/Terrain.h"

#include <memory>
#include <optional>
#include <vector>

namespace tessera::demo {

class DemoScene {
public:
    /// The flythrough advances a fixed step per frame, not wall time, so a
    /// given seed and frame index always give the same picture on any machine.
    static constexpr double kSecondsPerFrame = 1.0 / 30.0;

    /// Loads the height map (--heightmap or the generated content), builds the
    /// terrain, applies --splat craters and schedules --meteors impacts over
    /// `frames` frames; with --scene characters, loads the crowd.
    static Result<std::unique_ptr<DemoScene>> load(const DemoOptions& options, uint32_t frames);

    terrain::Terrain& terrain() { return *mTerrain; }
    /// The crowd of the characters scene; null in the terrain scene.
    CharacterCrowd* crowd() { return mCrowd.get(); }
    /// The camera at a frame: --camera when given, else the flythrough (or,
    /// in the characters scene, a slow circle around the crowd).
    scene::CameraPose cameraPose(uint32_t frame) const;
    /// Lands every impact due by `frame` on the terrain's CPU copy; the
    /// renderer takes them as pending splats for the GPU copy.
    void update(uint32_t frame);
    uint32_t impactsLanded() const { return mNextImpact; }

private:
    DemoScene() = default;

    std::unique_ptr<terrain::Terrain> mTerrain;
    std::unique_ptr<CharacterCrowd> mCrowd;
    std::optional<scene::CameraPath> mPath;
    std::optional<scene::CameraPose> mFixedPose;
    std::vector<terrain::MeteorImpact> mImpacts;
    uint32_t mNextImpact = 0;
};

} // namespace tessera::demo
