#pragma once
/// @file R2vbCommandPass.h
/// r2vb's last pass and R2VB step: one point per visible patch reads its
/// outer levels from the factor stream, adds its own detail term and inner
/// levels, and writes its record and its five emulated-tessellator commands
/// to seven render targets at once; the targets are then copied to the
/// record texel buffer and the indirect buffer that EmulatedTerrainBackend
/// draws from.

#include "R2vbRecording.h"
#include "common/TerrainBindings.h"
#include "R2vbTargets.h"
#include "tessera/gpu/FrameContext.h"
#include "tessera/gpu/Pipeline.h"
#include "tessera/gpu/PipelineLayout.h"

namespace tessera::backends {

class R2vbCommandPass {
public:
    R2vbCommandPass() = default;
    explicit R2vbCommandPass(gpu::Device& device);

    /// Records "r2vb.commands" and "r2vb.copyRecords" for `patches` visible
    /// patches and returns the record capacity (records and commands are laid
    /// out for it, EmulatedTerrainBackend.h). In adaptive mode
    /// targets.factorStream() must hold this frame's outer levels. Leaves the
    /// records visible to vertex shaders and the commands to indirect draws.
    uint32_t record(gpu::FrameContext& frame, R2vbTargets& targets, const gpu::Buffer& patchStream, uint32_t patches,
                    const gpu::Buffer& patchErrors, const gpu::Buffer& keyTable, const gpu::UniformSlice& tessUniforms,
                    const PushTerrainBindings& pushBindings);

private:
    void copyToBuffers(VkCommandBuffer cmd, R2vbTargets& targets, uint32_t rows, uint32_t capacity);

    gpu::PipelineLayout mLayout;
    gpu::Pipeline mPipeline;
};

} // namespace tessera::backends
