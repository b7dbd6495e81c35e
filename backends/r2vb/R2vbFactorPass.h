#pragma once
/// @file R2vbFactorPass.h
/// r2vb's second pass (the first paper's pass 2) and its R2VB step: one
/// point per edge of each visible patch fetches the edge's ends from the
/// cage target, evaluates the adaptive metric on them in vertex-ID order and
/// writes the level to a render target; the target is then copied to a
/// buffer that the command pass reads as a vertex stream.

#include "R2vbRecording.h"
#include "common/TerrainBindings.h"
#include "R2vbTargets.h"
#include "tessera/gpu/FrameContext.h"
#include "tessera/gpu/Pipeline.h"
#include "tessera/gpu/PipelineLayout.h"
#include "tessera/gpu/Sampler.h"

namespace tessera::backends {

class R2vbFactorPass {
public:
    R2vbFactorPass() = default;
    explicit R2vbFactorPass(gpu::Device& device);

    /// Records "r2vb.factors" (needs targets.cage() from R2vbCagePass) and
    /// "r2vb.copyFactors", which leaves targets.factorStream() ready for
    /// vertex-attribute reads. `edgeErrors` holds TerrainDetail's per-edge errors.
    void record(gpu::FrameContext& frame, R2vbTargets& targets, const gpu::Buffer& patchStream, uint32_t patches,
                const gpu::Buffer& edgeErrors, const gpu::UniformSlice& tessUniforms,
                const PushTerrainBindings& pushBindings);

private:
    void copyToStream(VkCommandBuffer cmd, R2vbTargets& targets, uint32_t patches);

    gpu::PipelineLayout mLayout;
    gpu::Pipeline mPipeline;
    gpu::Sampler mCageSampler; ///< texelFetch only, never filtered
};

} // namespace tessera::backends
