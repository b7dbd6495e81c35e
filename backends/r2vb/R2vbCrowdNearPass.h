#pragma once
/// @file R2vbCrowdNearPass.h
/// r2vb's passes for the emulated near tier of an instanced crowd (what
/// crowd_cull.comp's slot counter and crowd_skin.comp
/// do), after R2vbCrowdBinningPass, with render targets and copies only:
///   crowd.nearSlots     one point per slot s, the near tier's element s (a
///                       traversal of the pyramid's near channel): its
///                       CrowdNearSlot, copied into crowd.nearSlotRecords(),
///                       and its skin pass's indirect draw;
///   crowd.nearCommands  two points per (creature, slot): the 8-word indexed
///                       draw command, copied into crowd.nearCommands();
///   crowd.skin          per slot, an indirect point draw of its creature's
///                       cage from the crowd's vertex stream: each vertex
///                       skinned from the baked clip and compressed into its
///                       texel, copied into crowd.nearCages() (the R2VB step).

#include "R2vbCrowdRecording.h"
#include "tessera/gpu/FrameContext.h"
#include "tessera/gpu/Pipeline.h"
#include "tessera/gpu/PipelineLayout.h"
#include "tessera/gpu/Sampler.h"

namespace tessera::backends {

class R2vbCrowdNearPass {
public:
    R2vbCrowdNearPass() = default;
    explicit R2vbCrowdNearPass(gpu::Device& device);

    /// Outside the main pass, after R2vbCrowdBinningPass::record: the three
    /// passes above. Leaves the near slot records, commands and cages ready
    /// for EmulatedCrowdNearPass.
    void record(gpu::FrameContext& frame, r2vb::crowd::FrameInputs& in);

    /// GPU passes record() opens (for FrameReport::passes).
    static constexpr uint32_t kPasses = 3;

private:
    void writeSlots(VkCommandBuffer cmd, r2vb::crowd::FrameInputs& in);
    void writeCommands(VkCommandBuffer cmd, r2vb::crowd::FrameInputs& in);
    void skinCages(VkCommandBuffer cmd, r2vb::crowd::FrameInputs& in);

    gpu::Device* mDevice = nullptr;
    gpu::PipelineLayout mLayout;
    gpu::Sampler mSampler;
    gpu::Pipeline mSlots, mCommands, mSkin;
};

} // namespace tessera::backends
