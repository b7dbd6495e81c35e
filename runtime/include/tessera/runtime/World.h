#pragma once
/// @file World.h
/// The demo's world: the terrain (CPU copy and derived data), the scripted
/// camera flight over it, the meteor shower that deforms it and, in the
/// characters and crowd scenes, the characters walking on it.

#include "tessera/runtime/CharacterPopulation.h"
#include "tessera/runtime/Options.h"
#include "tessera/runtime/SimulatedCrowd.h"
#include "tessera/runtime/SubdivCharacters.h"
#include "tessera/runtime/SubdivModels.h"
#include "tessera/core/Result.h"
#include "tessera/scene/CameraPath.h"
#include "tessera/terrain/DrawnSurface.h"
#include "tessera/terrain/HeightField.h"
#include "tessera/terrain/MeteorShower.h"
#include "tessera/terrain/Terrain.h"

#include <memory>
#include <optional>
#include <vector>

namespace tessera::runtime {

/// The height map the options name: --heightmap, else the generated
/// content's terrain/height.png.
Result<terrain::HeightField> loadDemoHeightField(const Options& options);

class World {
public:
    /// The flythrough advances a fixed step per frame, not wall time, so a
    /// given seed and frame index always give the same picture on any machine.
    static constexpr double kSecondsPerFrame = 1.0 / 30.0;

    /// Loads the height map (loadDemoHeightField), builds the terrain,
    /// applies --splat craters, loads the characters (--scene characters) or
    /// creates the crowd (--scene crowd), and schedules --meteors impacts
    /// over `frames` frames.
    static Result<std::unique_ptr<World>> load(const Options& options, uint32_t frames);

    terrain::Terrain& terrain() { return *mTerrain; }
    /// The terrain as the backend draws it, where the characters stand: the
    /// frame loop updates it each frame before the characters (SceneRun).
    terrain::DrawnSurface& ground() { return *mGround; }
    /// The characters of the characters or crowd scene; null in the terrain scene.
    CharacterPopulation* characters() { return mCharacters.get(); }
    /// The characters scene's Catmull-Clark surfaces (--model FILE.obj);
    /// null when there are none.
    SubdivModels* surfaces() { return mSurfaces.get(); }
    /// The --model characters as Catmull-Clark surfaces
    /// (--character-surface catmull-clark or both); null otherwise.
    SubdivCharacters* subdivCharacters() { return mSubdivCharacters.get(); }
    /// The simulated crowd of the crowd scene (the same object as
    /// characters()); null in the other scenes.
    SimulatedCrowd* simulatedCrowd() { return mSimulated; }
    /// The camera at a frame: --camera when given, else the flythrough (or,
    /// in the characters and crowd scenes, a slow circle around them).
    scene::CameraPose cameraPose(uint32_t frame) const;
    /// Lands every impact due by `frame` on the terrain's CPU copy (the
    /// renderer takes them as pending splats for the GPU copy), then brings
    /// the crowd a step on (SimulatedCrowd::step: the step that ran ahead
    /// while the last frame was drawn, waited for before the craters land,
    /// so the crowd sees them from its next step).
    void update(uint32_t frame);
    /// Fixes the camera at `pose` from now on (as --camera does).
    void fixCamera(const scene::CameraPose& pose) { mFixedPose = pose; }
    /// Lets the scene's own camera (flythrough or orbit) fly again.
    void releaseCamera() { mFixedPose.reset(); }
    /// Lands a crater now (the window's meteor control): the CPU height
    /// field at once, the GPU copy with the next frame, the crowd's next step.
    void dropMeteor(const terrain::CraterSplat& splat);
    uint32_t impactsLanded() const { return mNextImpact; }

private:
    World() = default;
    void scheduleMeteors(const Options& options, uint32_t frames);

    std::unique_ptr<terrain::Terrain> mTerrain;
    std::unique_ptr<terrain::DrawnSurface> mGround;
    std::unique_ptr<CharacterPopulation> mCharacters;
    SimulatedCrowd* mSimulated = nullptr;
    std::unique_ptr<SubdivModels> mSurfaces;
    std::unique_ptr<SubdivCharacters> mSubdivCharacters;
    std::optional<scene::CameraPath> mPath;
    std::optional<scene::CameraPose> mFixedPose;
    std::vector<terrain::MeteorImpact> mImpacts;
    uint32_t mNextImpact = 0;
};

} // namespace tessera::runtime
