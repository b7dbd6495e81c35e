#pragma once
/// @file StreamoutSubdivFactorPass.h
/// "subdiv.factors" on streamout: one vertex-shader invocation per
/// tessellation domain of a subdivision surface computes its levels with
/// the shared tsSubdivLevels (hulldomain's hull stage: corner levels from
/// the refined LOD points, culling of holes and domains out of view),
/// clamps them to the emulated tessellator's [1, TS_EMU_MAX_LEVEL], and
/// transform feedback writes its record and its five tessellator commands
/// (zero for a culled domain) into the surface's StreamoutSubdivBuffers, as
/// streamout.factors does for terrain patches. Every domain writes its own
/// record r = domain, so nothing needs clearing and no draw-auto is needed.

#include "common/EmulatedDrawSource.h"
#include "common/GpuSubdiv.h"
#include "tessera/gpu/Buffer.h"
#include "tessera/gpu/FrameContext.h"
#include "tessera/gpu/Pipeline.h"
#include "tessera/gpu/PipelineLayout.h"

namespace tessera::backends {

class StreamoutSubdivFactorPass {
public:
    StreamoutSubdivFactorPass() = default;
    explicit StreamoutSubdivFactorPass(gpu::Device& device);

    /// Outside any render pass, after the refine pass. `uniforms` holds
    /// shader::SubdivUniforms, `keyTable` shader::TsEmuKeyTable. Leaves the
    /// records and commands ready for the emulated draw and returns them.
    EmulatedDrawSource record(gpu::FrameContext& frame, GpuSubdiv& surface, const gpu::UniformSlice& uniforms,
                              const gpu::Buffer& keyTable);

private:
    gpu::PipelineLayout mLayout;
    gpu::Pipeline mPipeline;
};

} // namespace tessera::backends
