#pragma once
/// @file ComputeSubdivRefinePass.h
/// The refine pass of the backends with compute (hulldomain, meshshader): a
/// dispatch that computes every control point and corner point of a
/// subdivision surface from this frame's cage (subdiv_refine.comp), one
/// invocation each, for the draw's shader reads.

#include "common/GpuSubdiv.h"
#include "tessera/gpu/ComputePipeline.h"
#include "tessera/gpu/FrameContext.h"
#include "tessera/gpu/PipelineLayout.h"

#include <string>

namespace tessera::backends {

class ComputeSubdivRefinePass {
public:
    ComputeSubdivRefinePass() = default;
    ComputeSubdivRefinePass(gpu::Device& device, const std::string& backendName);

    /// "subdiv.refine", outside any render pass: waits for `readers` (the
    /// draw's stages that read the points) of the previous frame, then leaves
    /// the refined points ready for them.
    void record(gpu::FrameContext& frame, GpuSubdiv& surface, VkPipelineStageFlags2 readers);

private:
    gpu::Device* mDevice = nullptr;
    gpu::PipelineLayout mLayout;
    gpu::ComputePipeline mPipeline;
};

} // namespace tessera::backends
