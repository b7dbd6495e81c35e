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

    World& world() { return *mWorld; }
    RenderSession& session() { return *mSession; }
    const scene::Camera& camera() const { return mCamera; }
    /// The instanced crowd when the backend draws one, else null.
    InstancedCrowd* instancedCrowd() { return mInstanced; }
    const lod::LodPolicy& lodPolicy() const { return mLodPolicy; }

private:
    SceneRun() = default;

    Options mOptions;
    std::unique_ptr<World> mWorld;
    std::unique_ptr<RenderSession> mSession;
    terrain::TessellationSettings mSettings;
    lod::LodPolicy mLodPolicy;
    InstancedCrowd* mInstanced = nullptr;
    scene::Camera mCamera;
    std::vector<SubdivDraw> mSubdivDraws; ///< the .obj shapes' and the Catmull-Clark characters' draws
};

} // namespace tessera::runtime
