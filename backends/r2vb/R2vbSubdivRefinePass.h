#pragma once
/// @file R2vbSubdivRefinePass.h
/// "subdiv.refine" and "subdiv.copyPoints" on r2vb (D3D9 style): one point
/// per refined point of a subdivision surface, placed on its own texel of
/// the surface's RGBA32F points target, whose vertex shader applies the
/// point's stencil to this frame's cage (tsSubdivRefinePoint, the sum
/// hulldomain's compute pass makes) and whose pixel shader writes it; then
/// the target's texels are copied into the surface's refined points (the
/// R2VB step), which later passes read as a texel buffer.

#include "common/GpuSubdiv.h"
#include "R2vbSubdivTargets.h"
#include "tessera/gpu/FrameContext.h"
#include "tessera/gpu/Pipeline.h"
#include "tessera/gpu/PipelineLayout.h"

namespace tessera::backends {

class R2vbSubdivRefinePass {
public:
    R2vbSubdivRefinePass() = default;
    explicit R2vbSubdivRefinePass(gpu::Device& device);

    /// Outside any render pass; leaves the refined points ready for the
    /// command pass's and the draw's shader reads.
    void record(gpu::FrameContext& frame, GpuSubdiv& surface, R2vbSubdivTargets& targets);

private:
    gpu::PipelineLayout mLayout;
    gpu::Pipeline mPipeline;
};

} // namespace tessera::backends
