#pragma once
/// @file SceneRun.h
/// One scene on one backend, frame by frame: the demo's world (World),
/// the render session, the tessellation settings, the LOD policy and, in the
/// characters and crowd scenes, the characters uploaded and the crowd made
/// instanced where the backend culls and bins crowds on the GPU. What the
/// flythrough and the crowd benchmark share.

#include "tessera/runtime/Options.h"
#include "tessera/runtime/World.h"
#include "tessera/runtime/InstancedCrowd.h"
#include "tessera/runtime/RenderSession.h"
#include "tessera/core/Result.h"
#include "tessera/lod/LodPolicy.h"
#include "tessera/scene/Camera.h"

#include <memory>
#include <vector>

namespace tessera::runtime {

class SceneRun {
public:
    /// Loads the scene for `frames` frames (World::load), creates the
    /// session on the options' backend and device, resolves the
    /// tessellation and the LOD policy, uploads the characters and makes
    /// the instanced crowd. One error naming the problem otherwise.
    static Result<std::unique_ptr<SceneRun>> create(const Options& options, uint32_t frames);

    /// Frame `frame`: the scene's update (meteors, the crowd's step), the
    /// camera, the characters' LOD and draws, and the render (read back
    /// when `readback`). Call between Profiler::beginFrame and endFrame.
    void renderFrame(uint32_t frame, bool readback);

    /// One turn of a host's frame loop: window events (false once the
    /// window was closed; nothing is drawn then), then renderFrame inside
    /// the profiler's frame `frame`. The image, when `readback`, comes from
    /// session().finish().
    bool step(uint32_t frame, bool readback);

    /// Re-creates the scene on backend `name` without restarting (the
    /// session keeps its device, window and target; the world keeps its
    /// state: craters, the crowd's simulation, the camera). Levels given for
    /// the old backend are clamped to the new one's. On failure the old
    /// backend draws on and the error says why.
    Status switchBackend(const std::string& name);
    /// Loads the world anew from `options` (another crowd size, other
    /// meteors) and re-creates the scene on the current backend, without
    /// restarting. On failure the old world stays and the error says why.
    Status reloadWorld(const Options& options);
    /// The options the scene runs with now (the backend after a switch).
    const Options& options() const { return mOptions; }
    /// Changes the options later frames draw with (wireframe, LOD colours,
    /// displacement, levels): what the overlay's controls set.
    Options& liveOptions() { return mOptions; }
    /// The terrain's tessellation as frames draw it; changes apply from the
    /// next frame.
    terrain::TessellationSettings& tessellation() { return mSettings; }
    World& world() { return *mWorld; }
    RenderSession& session() { return *mSession; }
    const scene::Camera& camera() const { return mCamera; }
    /// The instanced crowd when the backend draws one, else null.
    InstancedCrowd* instancedCrowd() { return mInstanced; }
    const lod::LodPolicy& lodPolicy() const { return mLodPolicy; }

private:
    SceneRun() = default;
    /// Everything that depends on the backend: the tessellation, the LOD
    /// policy, the characters, the crowd and the surfaces on the backend.
    Status attachScene(const Options& options);

    Options mOptions;
    uint32_t mFrames = 0;
    std::unique_ptr<World> mWorld;
    std::unique_ptr<RenderSession> mSession;
    terrain::TessellationSettings mSettings;
    lod::LodPolicy mLodPolicy;
    InstancedCrowd* mInstanced = nullptr;
    scene::Camera mCamera;
    std::vector<glm::vec4> mShadowCasters; ///< this frame's (CharacterPopulation::shadowCasters)
    std::vector<SubdivDraw> mSubdivDraws; ///< the .obj shapes' and the Catmull-Clark characters' draws
};

} // namespace tessera::runtime
