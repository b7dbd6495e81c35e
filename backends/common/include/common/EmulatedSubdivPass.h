#pragma once
/// @file EmulatedSubdivPass.h
/// The r2vb and streamout backends' subdivision-surface draw: the emulated
/// tessellator's pattern pieces (EmulatedTerrainBackend.h's contract, one
/// record per tessellation domain) through the evaluation vertex shader
/// subdiv_emulated.vert, which places each pattern point bit-identically to
/// hulldomain's gl_TessCoord and evaluates the shared subdiv_eval.glsl there
/// exactly as hulldomain's domain stage does; shading is subdiv.frag.

#include "common/SubdivPipelines.h"
#include "common/EmulatedDrawSource.h"
#include "common/GpuSubdiv.h"
#include "tessera/gpu/FrameContext.h"
#include "tessera/gpu/Pipeline.h"
#include "tessera/gpu/PipelineLayout.h"

#include <string>

namespace tessera::backends {

class EmulatedSubdivPass {
public:
    EmulatedSubdivPass() = default;
    /// Pipelines named "<backendName>.subdiv.<closed|twoSided>.<fill|wireframe>".
    EmulatedSubdivPass(gpu::Device& device, const std::string& backendName, VkFormat colorFormat,
                       VkFormat depthFormat, bool wireframe);

    /// "subdiv.draw", inside the main pass: every command of `source` over
    /// `patternVertices` (the pattern library's point references). The
    /// source's records and commands must be ready for vertex-shader and
    /// indirect reads, the surface's refined points for vertex-shader reads.
    void record(gpu::FrameContext& frame, GpuSubdiv& surface, const EmulatedDrawSource& source,
                const gpu::Buffer& patternVertices, const gpu::UniformSlice& frameUniforms,
                const gpu::UniformSlice& uniforms, bool wireframe);

private:
    gpu::Device* mDevice = nullptr;
    gpu::PipelineLayout mLayout;
    SubdivPipelines mPipelines;
};

} // namespace tessera::backends
