#pragma once
/// @file R2vbCrowdBinningPass.h
/// r2vb's crowd culling and LOD binning (D3D9 + R2VB style: render targets,
/// texel fetch, image-to-buffer copies and indirect draws only), the passes
/// that do what crowd_cull.comp does with atomics:
///   crowd.state     instances as points at their ids' texels: the LOD rule
///                   against last frame's state target, into this frame's;
///   crowd.classify  instances as points at their Morton-order texels of the
///                   histogram pyramid's base: per tier, 1 where the
///                   instance is in that tier's list;
///   crowd.pyramid   2 x 2 reductions up to 1 x 1;
///   crowd.args      per list, its count (rank of the creature's range end
///                   minus rank of its start, the upload being sorted by
///                   creature) copied over crowd.args(), and the indirect
///                   draw that extracts it;
///   crowd.lists     those draws: one point per entry finds its instance by a
///                   top-down traversal and writes its CrowdListEntry; the
///                   target's regions are copied into crowd.lists(), the
///                   middle and far draws' instance stream (the R2VB step).

#include "R2vbCrowdRecording.h"
#include "tessera/gpu/FrameContext.h"
#include "tessera/gpu/Pipeline.h"
#include "tessera/gpu/PipelineLayout.h"
#include "tessera/gpu/Sampler.h"

namespace tessera::backends {

class R2vbCrowdBinningPass {
public:
    R2vbCrowdBinningPass() = default;
    explicit R2vbCrowdBinningPass(gpu::Device& device);

    /// Outside the main pass: the five passes above. Leaves crowd.args() and
    /// crowd.lists() ready for indirect draws, vertex streams and copies, and
    /// the new state target and the pyramid sampled for the near passes.
    void record(gpu::FrameContext& frame, r2vb::crowd::FrameInputs& in);

    /// GPU passes record() opens (for FrameReport::passes).
    static constexpr uint32_t kPasses = 5;

private:
    void updateState(VkCommandBuffer cmd, r2vb::crowd::FrameInputs& in);
    void classify(VkCommandBuffer cmd, r2vb::crowd::FrameInputs& in);
    void reduce(VkCommandBuffer cmd, r2vb::crowd::FrameInputs& in);
    void writeArgs(VkCommandBuffer cmd, r2vb::crowd::FrameInputs& in);
    void extractLists(VkCommandBuffer cmd, r2vb::crowd::FrameInputs& in);
    VkDescriptorImageInfo sampled(const gpu::Image& image) const;

    gpu::Device* mDevice = nullptr;
    gpu::PipelineLayout mLayout;
    gpu::Sampler mSampler;
    gpu::Pipeline mState, mClassify, mReduce, mArgs, mLists;
};

} // namespace tessera::backends
