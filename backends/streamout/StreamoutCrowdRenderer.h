#pragma once
/// @file StreamoutCrowdRenderer.h
/// streamout's instanced crowds: the shared GpuCrowdSet (lists, commands and
/// near slots written by transform feedback) plus each crowd's own
/// StreamoutCrowdResources, the culling and binning passes that fill them
/// the D3D10 way (geometry-shader culling with stream output, a render
/// target for the LOD state, successive stream-out passes per tier,
/// transform-feedback queries copied into the indirect commands), and the
/// shared tier draws (EmulatedCrowdNearPass, CrowdMeshPass). Per frame:
///   crowd.cull    instances as points: LOD rule, survivors streamed out, state rasterised
///   crowd.bin     per tier and creature: the survivors streamed into the list, counted by a query
///   crowd.slots   near entries appended to the slot records; the near draws' commands streamed out
///   crowd.skin    the near slots' cages skinned and compressed by stream output
///   crowd.near, crowd.middle, crowd.far   the draws, inside the main pass

#include "common/CrowdMeshPass.h"
#include "common/EmulatedCrowdNearPass.h"
#include "common/GpuCrowdSet.h"
#include "StreamoutCrowdBinPass.h"
#include "StreamoutCrowdCullPass.h"
#include "StreamoutCrowdNearPass.h"
#include "StreamoutCrowdResources.h"
#include "tessera/core/Result.h"
#include "tessera/gpu/FrameContext.h"

#include <functional>
#include <memory>
#include <vector>

namespace tessera::backends {

class StreamoutCrowdRenderer {
public:
    /// Stream-out passes per frame, then the draws (FrameReport::passes).
    static constexpr uint32_t kPasses = 1 + TS_LOD_TIERS + 3 + TS_LOD_TIERS;

    StreamoutCrowdRenderer(gpu::Device& device, VkFormat colorFormat, VkFormat depthFormat);

    /// Fails, naming what the device's transform feedback lacks, where the
    /// crowd's passes cannot run (the backend's other passes may still).
    Result<backend::CrowdHandle> create(const backend::CrowdDesc& desc,
                                        const std::function<GpuCharacter*(backend::CharacterHandle)>& find);
    void destroy(backend::CrowdHandle handle);
    GpuCrowd* find(backend::CrowdHandle handle) { return mCrowds.find(handle); }
    Result<backend::CrowdTiers> readTiers(backend::CrowdHandle handle) { return mCrowds.readTiers(handle); }

    /// Outside the main pass: every culling and binning pass of `crowd`
    /// (`handle`) for this frame; `uniforms` holds its shader::CrowdUniforms.
    void recordPasses(gpu::FrameContext& frame, backend::CrowdHandle handle, const gpu::UniformSlice& uniforms);
    /// Inside the main pass: the tier draws.
    void recordDraws(gpu::FrameContext& frame, GpuCrowd& crowd, const gpu::UniformSlice& frameUniforms,
                     const gpu::UniformSlice& uniforms);

    /// Device bytes of the crowd and its stream-out resources.
    uint64_t bytes(backend::CrowdHandle handle);

private:
    Status checkCrowd(const GpuCrowd& crowd) const;

    gpu::Device& mDevice;
    VkPhysicalDeviceTransformFeedbackPropertiesEXT mXfb{};
    GpuCrowdSet mCrowds;
    std::vector<std::unique_ptr<StreamoutCrowdResources>> mResources; ///< by handle; null once destroyed
    gpu::PipelineLayout mLayout;
    StreamoutCrowdCullPass mCull;
    StreamoutCrowdBinPass mBin;
    StreamoutCrowdNearPass mNearPass1;
    EmulatedCrowdNearPass mNear;
    CrowdMeshPass mMesh;
};

} // namespace tessera::backends
