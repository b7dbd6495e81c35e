#pragma once
/// @file StreamoutSubdivRefinePass.h
/// "subdiv.refine" on streamout (D3D10 style): one point per refined point
/// of a subdivision surface through a vertex shader that applies its
/// stencil to this frame's cage (tsSubdivRefinePoint, the same sum as
/// hulldomain's compute pass), captured by transform feedback straight into
/// the surface's refined points, with the rasterizer off.

#include "common/GpuSubdiv.h"
#include "tessera/gpu/FrameContext.h"
#include "tessera/gpu/Pipeline.h"
#include "tessera/gpu/PipelineLayout.h"

namespace tessera::backends {

class StreamoutSubdivRefinePass {
public:
    StreamoutSubdivRefinePass() = default;
    explicit StreamoutSubdivRefinePass(gpu::Device& device);

    /// Outside any render pass; leaves the points ready for the factor
    /// pass's and the draw's shader reads.
    void record(gpu::FrameContext& frame, GpuSubdiv& surface);

private:
    gpu::PipelineLayout mLayout;
    gpu::Pipeline mPipeline;
};

} // namespace tessera::backends
