#pragma once
/// @file R2vbCagePass.h
/// r2vb's first pass (the first paper's pass 1): the visible patches' cage
/// rendered as points into a render target, one texel per corner holding the
/// displaced corner and its grid vertex ID, for the factor pass to fetch.

#include "R2vbRecording.h"
#include "common/TerrainBindings.h"
#include "R2vbTargets.h"
#include "tessera/gpu/FrameContext.h"
#include "tessera/gpu/Pipeline.h"
#include "tessera/gpu/PipelineLayout.h"

namespace tessera::backends {

class R2vbCagePass {
public:
    R2vbCagePass() = default;
    explicit R2vbCagePass(gpu::Device& device);

    /// Records "r2vb.cage" for `patches` visible patches whose indices are in
    /// `patchStream`, and leaves targets.cage() SHADER_READ_ONLY_OPTIMAL and
    /// visible to vertex-shader fetches.
    void record(gpu::FrameContext& frame, R2vbTargets& targets, const gpu::Buffer& patchStream, uint32_t patches,
                const gpu::UniformSlice& tessUniforms, const PushTerrainBindings& pushBindings);

private:
    gpu::PipelineLayout mLayout;
    gpu::Pipeline mPipeline;
};

} // namespace tessera::backends
