#pragma once
/// @file R2vbCharacterSkinPass.h
/// r2vb's pass 1 of the two-pass character path (D3D9 style): render-target
/// recirculation only. Each cage vertex is drawn as one point into an
/// RGBA32UI target (skinned and compressed in the vertex shader, written by
/// the pixel shader), and the target's rows are copied into the instance's
/// compressed cage buffer, which the tessellation pass reads as a vertex
/// texture (the R2VB step). No compute, no storage writes.

#include "common/BasicCharacterBackend.h"
#include "tessera/gpu/Image.h"
#include "tessera/gpu/Pipeline.h"
#include "tessera/gpu/PipelineLayout.h"

namespace tessera::backends {

class R2vbCharacterSkinPass {
public:
    R2vbCharacterSkinPass() = default;
    explicit R2vbCharacterSkinPass(gpu::Device& device);

    void record(gpu::FrameContext& frame, const CharacterInstance& instance, const CharacterPushFn& push);
    /// Bytes of the render target (grown to the largest cage drawn).
    uint64_t bytes() const;

private:
    gpu::Image& targetFor(uint32_t vertices);

    gpu::Device* mDevice = nullptr;
    gpu::PipelineLayout mLayout;
    gpu::Pipeline mPipeline;
    gpu::Image mTarget;
};

} // namespace tessera::backends
