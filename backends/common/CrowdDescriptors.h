#pragma once
/// @file CrowdDescriptors.h
/// The push-descriptor writes of an instanced crowd pass (the bindings of
/// CrowdInstance.h plus the frame's and a creature's maps) and the one
/// pipeline layout every crowd pipeline of a backend shares, so compute and
/// draws bind alike.

#include "GpuCrowd.h"
#include "tessera/gpu/FrameContext.h"
#include "tessera/gpu/PipelineLayout.h"

#include <array>
#include <span>
#include <string>

namespace tessera::backends {

class CrowdDescriptors {
public:
    /// The layout: every crowd binding, visible to `stages`.
    static gpu::PipelineLayout layout(gpu::Device& device, VkShaderStageFlags stages, std::string name);

    /// Writes for `crowd` in frame slot `slot` with this frame's uniforms.
    CrowdDescriptors(GpuCrowd& crowd, uint32_t slot, const gpu::UniformSlice& frame, const gpu::UniformSlice& uniforms);
    CrowdDescriptors(const CrowdDescriptors&) = delete;
    CrowdDescriptors& operator=(const CrowdDescriptors&) = delete;

    /// Every write, with creature `creature`'s maps.
    std::span<const VkWriteDescriptorSet> writes(uint32_t creature);

private:
    static constexpr size_t kBuffers = 10;
    static constexpr size_t kImages = 3;
    GpuCrowd& mCrowd;
    std::array<VkDescriptorBufferInfo, kBuffers> mBuffers{};
    std::array<VkDescriptorImageInfo, kImages> mImages{};
    VkBufferView mBaked = VK_NULL_HANDLE;
    std::array<VkWriteDescriptorSet, kBuffers + kImages + 1> mWrites{};
};

} // namespace tessera::backends
