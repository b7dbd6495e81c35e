#pragma once
/// @file SkyPass.h
/// The full look's sky (docs/LOOKS.md): one fullscreen triangle at the far
/// plane, drawn last in the main pass with the depth test and no depth write,
/// so only pixels no geometry covered shade the analytic sky
/// (sky_atmosphere.glsl). Vertex and fragment shaders only, so every backend,
/// D3D9-style included, draws it the same way.

#include "tessera/gpu/FrameContext.h"
#include "tessera/gpu/Pipeline.h"
#include "tessera/gpu/PipelineLayout.h"

#include <string>

namespace tessera::backends {

class SkyPass {
public:
    SkyPass() = default;
    /// Pipeline for the main target's formats (the backend's BackendInitInfo).
    SkyPass(gpu::Device& device, const std::string& backendName, VkFormat colorFormat, VkFormat depthFormat);

    /// Records the "sky" pass into the open main pass; `frameUniforms` is the
    /// frame's FrameUniforms slice.
    void record(gpu::FrameContext& frame, const gpu::UniformSlice& frameUniforms);

private:
    gpu::Device* mDevice = nullptr;
    gpu::PipelineLayout mLayout;
    gpu::Pipeline mPipeline;
};

} // namespace tessera::backends
