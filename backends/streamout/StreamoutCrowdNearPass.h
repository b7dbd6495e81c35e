#pragma once
/// @file StreamoutCrowdNearPass.h
/// streamout's crowd near tier, pass 1, with stream output alone:
///  - "crowd.slots": per creature a draw over its near list (a point per
///    entry, the count its bin query left in an indirect command) appends a
///    CrowdNearSlot per entry to crowd.nearSlotRecords(), all in one
///    transform-feedback session, so creature c's entries follow those of
///    creatures 0..c-1 (past the last slot the buffer is full and the rest
///    is dropped); then one point per (creature, slot) streams out the near
///    draw's indexed indirect commands into crowd.nearCommands().
///  - "crowd.skin": per creature an indirect draw of nearStride points,
///    instanced over its near list (the instance count copied from the
///    list's query), streams out each slot's compressed cage into
///    crowd.nearCages(), again in one session, so each entry's cage lands in
///    the slot its record took.

#include "common/GpuCrowd.h"
#include "StreamoutCrowdBindings.h"
#include "StreamoutCrowdResources.h"
#include "tessera/gpu/FrameContext.h"
#include "tessera/gpu/Pipeline.h"
#include "tessera/gpu/PipelineLayout.h"

namespace tessera::backends {

class StreamoutCrowdNearPass {
public:
    StreamoutCrowdNearPass() = default;
    StreamoutCrowdNearPass(gpu::Device& device, const gpu::PipelineLayout& layout);

    /// Records both passes after the bin pass, with the slot records cleared
    /// this frame; leaves the records, the
    /// commands and the cages ready for EmulatedCrowdNearPass.
    void record(gpu::FrameContext& frame, GpuCrowd& crowd, StreamoutCrowdResources& resources,
                const StreamoutCrowdBindings& bindings);

private:
    void recordSlots(gpu::FrameContext& frame, GpuCrowd& crowd, StreamoutCrowdResources& resources,
                     const StreamoutCrowdBindings& bindings);
    void recordSkin(gpu::FrameContext& frame, GpuCrowd& crowd, StreamoutCrowdResources& resources,
                    const StreamoutCrowdBindings& bindings);

    const gpu::PipelineLayout* mLayout = nullptr;
    gpu::Pipeline mSlots;
    gpu::Pipeline mCommands;
    gpu::Pipeline mSkin;
};

} // namespace tessera::backends
