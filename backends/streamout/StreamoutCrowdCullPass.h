#pragma once
/// @file StreamoutCrowdCullPass.h
/// GPU pass "crowd.cull" of streamout's crowd (the Froblins' D3D10 culling):
/// per creature its instances drawn as points; the vertex stage runs the
/// shared LOD rule against last frame's state (loaded from one state render
/// target), the geometry stage drops the instances out of view or out of the
/// budget and emits each survivor once, which both streams its record out
/// into the creature's survivors region (counted by a stream query) and
/// is rasterised into the other state target at its id's texel, writing its
/// next state. That target is cleared to tsLodStateNone() first, so every
/// id not drawn this frame starts the next one out of view.

#include "common/GpuCrowd.h"
#include "StreamoutCrowdBindings.h"
#include "StreamoutCrowdResources.h"
#include "tessera/gpu/FrameContext.h"
#include "tessera/gpu/Pipeline.h"
#include "tessera/gpu/PipelineLayout.h"

namespace tessera::backends {

class StreamoutCrowdCullPass {
public:
    StreamoutCrowdCullPass() = default;
    StreamoutCrowdCullPass(gpu::Device& device, const gpu::PipelineLayout& layout);

    /// Resets this frame's indirect commands (initialArgs()), queries and
    /// near slot records, records the pass, then leaves the survivors ready
    /// for vertex input, their counts in the bin pass's indirect draws, and
    /// the written state target ready to be read next
    /// frame (the targets swap).
    void record(gpu::FrameContext& frame, GpuCrowd& crowd, StreamoutCrowdResources& resources,
                const StreamoutCrowdBindings& bindings);

private:
    void reset(VkCommandBuffer cmd, GpuCrowd& crowd, StreamoutCrowdResources& resources);

    const gpu::PipelineLayout* mLayout = nullptr;
    gpu::Pipeline mPipeline;
};

} // namespace tessera::backends
