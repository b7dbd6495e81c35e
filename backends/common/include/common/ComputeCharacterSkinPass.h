#pragma once
/// @file ComputeCharacterSkinPass.h
/// Pass 1 of the two-pass character path on the backends with compute
/// (hulldomain, meshshader): a compute shader (character_skin.comp) skins
/// every cage vertex once and writes the 128-bit compressed vertex to a
/// storage buffer.

#include "common/BasicCharacterBackend.h"
#include "tessera/gpu/ComputePipeline.h"
#include "tessera/gpu/PipelineLayout.h"

#include <string>

namespace tessera::backends {

class ComputeCharacterSkinPass {
public:
    ComputeCharacterSkinPass() = default;
    ComputeCharacterSkinPass(gpu::Device& device, const std::string& backendName);

    /// Dispatches one invocation per cage vertex into `instance.compressed`,
    /// then makes the writes visible to `reader` (the stage that loads the
    /// cage: vertex, mesh).
    void record(gpu::FrameContext& frame, const CharacterInstance& instance, const CharacterPushFn& push,
                VkPipelineStageFlags2 reader);

private:
    gpu::PipelineLayout mLayout;
    gpu::ComputePipeline mPipeline;
};

} // namespace tessera::backends
