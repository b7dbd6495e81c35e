#pragma once
/// @file HulldomainCharacterSkinPass.h
/// hulldomain's pass 1 of the two-pass character path (D3D11 style): a
/// compute shader skins every cage vertex once and writes the 128-bit
/// compressed vertex to a storage buffer.

#include "common/BasicCharacterBackend.h"
#include "tessera/gpu/ComputePipeline.h"
#include "tessera/gpu/PipelineLayout.h"

namespace tessera::backends {

class HulldomainCharacterSkinPass {
public:
    HulldomainCharacterSkinPass() = default;
    explicit HulldomainCharacterSkinPass(gpu::Device& device);

    /// Dispatches one invocation per cage vertex into `instance.compressed`,
    /// then makes the writes visible to vertex-shader reads.
    void record(gpu::FrameContext& frame, const CharacterInstance& instance, const CharacterPushFn& push);

private:
    gpu::PipelineLayout mLayout;
    gpu::ComputePipeline mPipeline;
};

} // namespace tessera::backends
