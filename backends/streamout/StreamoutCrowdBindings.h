#pragma once
/// @file StreamoutCrowdBindings.h
/// The descriptors of streamout's crowd culling and binning passes: one
/// pipeline layout for all of them (the crowd uniforms, the frame's
/// instances, baked clips and near slot records as texel buffers, the LOD
/// state target, the cage texels; push constants streamout_crowd.glsl
/// describes) and the push-descriptor writes of one frame.

#include "common/GpuCrowd.h"
#include "StreamoutCrowdResources.h"
#include "tessera/gpu/FrameContext.h"
#include "tessera/gpu/PipelineLayout.h"

#include <array>
#include <cstdint>

namespace tessera::backends {

class StreamoutCrowdBindings {
public:
    /// The layout every crowd pass of streamout uses.
    static gpu::PipelineLayout layout(gpu::Device& device);

    /// This frame's writes: `uniforms` holds shader::CrowdUniforms, the
    /// state read is `resources.stateRead()`.
    StreamoutCrowdBindings(GpuCrowd& crowd, StreamoutCrowdResources& resources, uint32_t slot,
                           const gpu::UniformSlice& uniforms);
    StreamoutCrowdBindings(const StreamoutCrowdBindings&) = delete;
    StreamoutCrowdBindings& operator=(const StreamoutCrowdBindings&) = delete;

    /// Pushes the writes and the push constants (tier, creature, cage base)
    /// for the bound graphics pipeline of `layout`.
    void push(gpu::FrameContext& frame, const gpu::PipelineLayout& layout, uint32_t tier, uint32_t creature,
              uint32_t cageBase) const;

private:
    static constexpr size_t kTexels = 6;
    VkDescriptorBufferInfo mUniforms{};
    std::array<VkBufferView, kTexels> mTexels{};
    VkDescriptorImageInfo mState{};
    std::array<VkWriteDescriptorSet, kTexels + 2> mWrites{};
};

} // namespace tessera::backends
