#pragma once
/// @file StreamoutCrowdPasses.h
/// streamout's culling and binning of an instanced crowd, the D3D10 way
/// (the Froblins' technique): geometry-shader culling with stream output, a
/// render target for the LOD state, successive stream-out passes per tier,
/// transform-feedback queries copied into the indirect commands. They write
/// the shared GpuCrowd's lists, commands and near slots (by transform
/// feedback) with each crowd's own StreamoutCrowdResources, its
/// TechniqueExtension. Per frame, outside the main pass:
///   crowd.cull    instances as points: LOD rule, survivors streamed out, state rasterised
///   crowd.bin     per tier and creature: the survivors streamed into the list, counted by a query
///   crowd.slots   near entries appended to the slot records; the near draws' commands streamed out
///   crowd.skin    the near slots' cages skinned and compressed by stream output
/// EmulatedTerrainBackend then draws the tiers (crowd.near, crowd.middle,
/// crowd.far) inside the main pass.

#include "StreamoutCrowdBinPass.h"
#include "StreamoutCrowdCullPass.h"
#include "StreamoutCrowdNearPass.h"
#include "StreamoutCrowdResources.h"
#include "common/GpuCrowd.h"
#include "tessera/core/Result.h"
#include "tessera/gpu/FrameContext.h"
#include "tessera/gpu/PipelineLayout.h"

#include <memory>

namespace tessera::backends {

class StreamoutCrowdPasses {
public:
    /// Stream-out passes record() opens (FrameReport::passes; the tier draws
    /// add TS_LOD_TIERS).
    static constexpr uint32_t kPasses = 1 + TS_LOD_TIERS + 3;

    /// The passes share one layout, which they point at: keep this object
    /// where it was made.
    explicit StreamoutCrowdPasses(gpu::Device& device);
    StreamoutCrowdPasses(const StreamoutCrowdPasses&) = delete;
    StreamoutCrowdPasses& operator=(const StreamoutCrowdPasses&) = delete;

    /// `crowd`'s stream-out resources; fails, naming what the device's
    /// transform feedback lacks, where the crowd's passes cannot run (the
    /// backend's other passes may still).
    Result<std::unique_ptr<StreamoutCrowdResources>> createResources(GpuCrowd& crowd) const;

    /// Outside the main pass: every culling and binning pass of `crowd`
    /// for this frame; `uniforms` holds its shader::CrowdUniforms.
    void record(gpu::FrameContext& frame, GpuCrowd& crowd, StreamoutCrowdResources& resources,
                const gpu::UniformSlice& uniforms);

private:
    Status checkCrowd(const GpuCrowd& crowd) const;

    gpu::Device& mDevice;
    VkPhysicalDeviceTransformFeedbackPropertiesEXT mXfb{};
    gpu::PipelineLayout mLayout;
    StreamoutCrowdCullPass mCull;
    StreamoutCrowdBinPass mBin;
    StreamoutCrowdNearPass mNearPass1;
};

} // namespace tessera::backends
