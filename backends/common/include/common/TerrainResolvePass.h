#pragma once
/// @file TerrainResolvePass.h
/// The full look's deferred terrain shading (docs/LOOKS.md, "Deferred
/// terrain shading"). In the full look the terrain's main-pass fragments
/// store their distance from the camera in the target's RGB with alpha 0;
/// after the main pass this shades every such pixel once from it (the
/// terrain is a height field: position, normal and materials all follow) and
/// (Mode::Compute) every uncovered pixel with the sky, keeping the pixels characters and
/// surfaces shaded forward (alpha 1).
///
/// Two ways to run the same shader code (terrain_resolve.glsl):
/// - Mode::Compute, a compute dispatch reading and writing the main target as
///   a storage image: for backends with compute (hulldomain). On GPUs that
///   run fragment shaders on a few of their cores (the H100) it costs a
///   fraction of a fullscreen pass.
/// - Mode::Fragment, a copy of the target, then a fullscreen triangle at the
///   far plane that reads the copy and writes the target where the depth
///   test (GREATER) finds something drawn: vertex and fragment shaders and a
///   copy only, so the D3D9- and D3D10-style backends run it. The sky pass
///   has drawn the sky in the main pass.

#include "common/TerrainBindings.h"
#include "tessera/gpu/ComputePipeline.h"
#include "tessera/gpu/FrameContext.h"
#include "tessera/gpu/Image.h"
#include "tessera/gpu/Pipeline.h"
#include "tessera/gpu/PipelineLayout.h"
#include "tessera/gpu/Sampler.h"

#include <memory>
#include <span>
#include <string>

namespace tessera::backends {

class TerrainResolvePass {
public:
    enum class Mode { Fragment, Compute };

    TerrainResolvePass() = default;
    /// `colorFormat` and `depthFormat` are the main target's (Mode::Fragment
    /// renders into it, depth-testing against what the main pass drew).
    TerrainResolvePass(gpu::Device& device, const std::string& backendName, Mode mode, VkFormat colorFormat,
                       VkFormat depthFormat);

    Mode mode() const { return mMode; }

    /// Records the pass "terrain.resolve" after the main pass has ended,
    /// leaving the target's colour in COLOR_ATTACHMENT_OPTIMAL, as the main
    /// pass does.
    void record(gpu::FrameContext& frame, const PushTerrainBindings& pushTerrain);

private:
    void recordCompute(gpu::FrameContext& frame, const PushTerrainBindings& pushTerrain);
    void recordFragment(gpu::FrameContext& frame, const PushTerrainBindings& pushTerrain);

    gpu::Device* mDevice = nullptr;
    Mode mMode = Mode::Fragment;
    gpu::PipelineLayout mLayout;
    gpu::Pipeline mPipeline;
    gpu::ComputePipeline mComputePipeline;
    gpu::Sampler mSourceSampler;
    /// Mode::Fragment's copy of the target, re-created when the target's size changes.
    std::unique_ptr<gpu::Image> mSource;
};

} // namespace tessera::backends
