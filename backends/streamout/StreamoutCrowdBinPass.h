#pragma once
/// @file StreamoutCrowdBinPass.h
/// GPU pass "crowd.bin" of streamout's crowd: LOD binning by successive
/// stream-out passes. First a split per creature copies the survivors the
/// mesh tiers can take into the mesh survivors (streamout_crowd_split.geom);
/// then one pass per (tier, creature) list draws the creature's mesh
/// survivors (near, middle, far) or all its survivors (impostor) as points
/// (an indirect draw whose count the split's or the cull pass's query left)
/// through a geometry shader that emits the entries of the tier
/// (streamout_crowd_bin.geom) into the list's region of crowd.lists(),
/// inside a transform-feedback stream query. Most of a large crowd is
/// impostors: two passes read every survivor, not four. The queries' results are
/// copied on the GPU into the indirect commands' instance counts and the
/// near passes' draws, so nothing waits on the CPU.

#include "common/GpuCrowd.h"
#include "StreamoutCrowdBindings.h"
#include "StreamoutCrowdResources.h"
#include "tessera/gpu/FrameContext.h"
#include "tessera/gpu/Pipeline.h"
#include "tessera/gpu/PipelineLayout.h"

namespace tessera::backends {

class StreamoutCrowdBinPass {
public:
    StreamoutCrowdBinPass() = default;
    StreamoutCrowdBinPass(gpu::Device& device, const gpu::PipelineLayout& layout);

    /// Records the pass after the cull pass (the survivors and their counts
    /// ready) and with crowd.args() already reset to initialArgs(); leaves the
    /// lists ready for vertex input and the counts in crowd.args() and
    /// resources.draws() ready for indirect draws and transfers.
    void record(gpu::FrameContext& frame, GpuCrowd& crowd, StreamoutCrowdResources& resources,
                const StreamoutCrowdBindings& bindings);

private:
    /// The split, with the mesh survivors' counts copied into their draws.
    void split(gpu::FrameContext& frame, GpuCrowd& crowd, StreamoutCrowdResources& resources,
               const StreamoutCrowdBindings& bindings);
    void copyCounts(VkCommandBuffer cmd, GpuCrowd& crowd, StreamoutCrowdResources& resources);

    const gpu::PipelineLayout* mLayout = nullptr;
    gpu::Pipeline mPipeline, mSplitPipeline;
};

} // namespace tessera::backends
