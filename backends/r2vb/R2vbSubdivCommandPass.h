#pragma once
/// @file R2vbSubdivCommandPass.h
/// "subdiv.commands" and "subdiv.copyRecords" on r2vb: one point per
/// tessellation domain of a subdivision surface computes its levels with
/// the shared tsSubdivLevels (hulldomain's hull stage), clamped to the
/// emulated tessellator's [1, TS_EMU_MAX_LEVEL], and writes its record and
/// its five tessellator commands (zero when culled) to seven render targets
/// at once, as r2vb.commands does for terrain patches (with the same pixel
/// shader); the targets are then copied to the surface's record texel
/// buffer and indirect buffer (R2VB).

#include "common/EmulatedDrawSource.h"
#include "common/GpuSubdiv.h"
#include "R2vbSubdivTargets.h"
#include "tessera/gpu/Buffer.h"
#include "tessera/gpu/FrameContext.h"
#include "tessera/gpu/Pipeline.h"
#include "tessera/gpu/PipelineLayout.h"

namespace tessera::backends {

class R2vbSubdivCommandPass {
public:
    R2vbSubdivCommandPass() = default;
    explicit R2vbSubdivCommandPass(gpu::Device& device);

    /// Outside any render pass, after the refine pass. `uniforms` holds
    /// shader::SubdivUniforms, `keyTable` shader::TsEmuKeyTable. Leaves the
    /// records and commands ready for the emulated draw and returns them.
    EmulatedDrawSource record(gpu::FrameContext& frame, GpuSubdiv& surface, R2vbSubdivTargets& targets,
                              const gpu::UniformSlice& uniforms, const gpu::Buffer& keyTable);

private:
    void copyToBuffers(VkCommandBuffer cmd, R2vbSubdivTargets& targets);

    gpu::PipelineLayout mLayout;
    gpu::Pipeline mPipeline;
};

} // namespace tessera::backends
