#pragma once
/// @file StreamoutCharacterSkinPass.h
/// streamout's pass 1 of the two-pass character path (D3D10 style): the cage
/// drawn as points through a vertex shader that skins and compresses each
/// vertex, captured by transform feedback into the instance's compressed
/// cage buffer, with the rasterizer off.

#include "common/BasicCharacterBackend.h"
#include "tessera/gpu/Pipeline.h"
#include "tessera/gpu/PipelineLayout.h"

namespace tessera::backends {

class StreamoutCharacterSkinPass {
public:
    StreamoutCharacterSkinPass() = default;
    explicit StreamoutCharacterSkinPass(gpu::Device& device);

    void record(gpu::FrameContext& frame, const CharacterInstance& instance, const CharacterPushFn& push);

private:
    gpu::PipelineLayout mLayout;
    gpu::Pipeline mPipeline;
};

} // namespace tessera::backends
