#pragma once
/// @file ComputeCrowdCullPass.h
/// An instanced crowd's culling, LOD binning and near-tier skinning in
/// compute, shared by the backends with compute shaders (hulldomain,
/// meshshader): crowd_cull.comp runs the shared LOD rule per instance and
/// appends it to the tier lists (GpuCrowd), whose counts are the instance
/// counts of the indirect draws; crowd_skin.comp, dispatched indirectly by
/// the near slots the culling filled, skins each near slot's cage into the
/// paper's 128-bit compressed vertices. What draws the lists is the
/// backend's (hull/domain stages, task/mesh stages).

#include "common/CrowdDescriptors.h"
#include "common/GpuCrowd.h"
#include "tessera/gpu/ComputePipeline.h"
#include "tessera/gpu/FrameContext.h"
#include "tessera/gpu/PipelineLayout.h"

#include <functional>
#include <string>

namespace tessera::backends {

class ComputeCrowdCullPass {
public:
    ComputeCrowdCullPass() = default;
    /// Pipelines named `<backendName>.crowd.cull` and `.crowd.skin`.
    ComputeCrowdCullPass(gpu::Device& device, const std::string& backendName);

    /// Outside the main pass: resets the indirect commands, culls and bins
    /// `instanceCount` instances (GPU pass crowd.cull), then skins the near
    /// slots (crowd.skin) and makes the compressed cages visible to
    /// `nearReader` (the stages that read them: vertex, mesh). `binned`, when
    /// given, records more work inside crowd.cull once the lists and their
    /// counts are complete and visible to compute and indirect reads (a
    /// technique deriving its own commands from the counts).
    void record(gpu::FrameContext& frame, GpuCrowd& crowd, CrowdDescriptors& descriptors, uint32_t instanceCount,
                VkPipelineStageFlags2 nearReader, const std::function<void(VkCommandBuffer)>& binned = {});

    /// The compute layout (the crowd's Storage bindings, compute only), for
    /// a technique's own compute passes over the same writes.
    const gpu::PipelineLayout& layout() const { return mLayout; }

private:
    void push(VkCommandBuffer cmd, CrowdDescriptors& descriptors);

    gpu::Device* mDevice = nullptr;
    gpu::PipelineLayout mLayout;
    gpu::ComputePipeline mCull;
    gpu::ComputePipeline mSkin;
};

} // namespace tessera::backends
