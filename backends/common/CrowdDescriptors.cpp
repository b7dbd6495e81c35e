#include "CrowdDescriptors.h"

#include "CharacterUniforms.h"
#include "CommandHelpers.h"
#include "FrameUniforms.h"

namespace tessera::backends {
namespace {

constexpr VkDescriptorType kUniform = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
constexpr VkDescriptorType kStorage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;

// Binding and type of each buffer write, in CrowdDescriptors::mBuffers' order.
constexpr std::pair<uint32_t, VkDescriptorType> kBufferBindings[] = {
    {TS_BINDING_FRAME, kUniform},          {TS_BINDING_CROWD, kUniform},
    {TS_BINDING_CROWD_INSTANCES, kStorage}, {TS_BINDING_CROWD_LISTS, kStorage},
    {TS_BINDING_CROWD_CLIPS, kStorage},    {TS_BINDING_CROWD_VERTICES, kStorage},
    {TS_BINDING_CROWD_STATE, kStorage},    {TS_BINDING_CROWD_ARGS, kStorage},
    {TS_BINDING_CROWD_NEAR, kStorage},     {TS_BINDING_CROWD_SLOTS, kStorage}};
constexpr uint32_t kImageBindings[] = {TS_BINDING_BASE_COLOR, TS_BINDING_NORMAL_MAP, TS_BINDING_DISPLACEMENT};

} // namespace

gpu::PipelineLayout CrowdDescriptors::layout(gpu::Device& device, VkShaderStageFlags stages, std::string name) {
    std::vector<gpu::BindingDesc> bindings;
    for (const auto& [binding, type] : kBufferBindings) bindings.push_back({binding, type, stages});
    bindings.push_back({TS_BINDING_CROWD_BAKED, VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER, stages});
    for (uint32_t binding : kImageBindings)
        bindings.push_back({binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, stages});
    return gpu::PipelineLayout(device, bindings, 0, 0, std::move(name));
}

CrowdDescriptors::CrowdDescriptors(GpuCrowd& crowd, uint32_t slot, const gpu::UniformSlice& frame,
                                   const gpu::UniformSlice& uniforms)
    : mCrowd(crowd) {
    auto whole = [](gpu::Buffer& b) { return VkDescriptorBufferInfo{b.handle(), 0, VK_WHOLE_SIZE}; };
    mBuffers = {frame.descriptor(),         uniforms.descriptor(),     whole(crowd.instances(slot)),
                whole(crowd.lists()),        whole(crowd.clips()),      whole(crowd.vertices()),
                whole(crowd.state()),        whole(crowd.args()),       whole(crowd.nearCages()),
                whole(crowd.nearOwners())};
    mBaked = crowd.bakedView();
    for (size_t i = 0; i < kBuffers; ++i)
        mWrites[i] = bufferWrite(kBufferBindings[i].first, kBufferBindings[i].second, &mBuffers[i]);
    mWrites[kBuffers] = texelWrite(TS_BINDING_CROWD_BAKED, &mBaked);
    for (size_t i = 0; i < kImages; ++i) mWrites[kBuffers + 1 + i] = imageWrite(kImageBindings[i], &mImages[i]);
}

std::span<const VkWriteDescriptorSet> CrowdDescriptors::writes(uint32_t creature) {
    GpuCharacter& c = *mCrowd.creatures()[creature].character;
    const VkImageLayout read = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    mImages = {VkDescriptorImageInfo{c.sampler().handle(), c.baseColor().view(), read},
               VkDescriptorImageInfo{c.sampler().handle(), c.normalMap().view(), read},
               VkDescriptorImageInfo{c.sampler().handle(), c.displacementMap().view(), read}};
    return mWrites;
}

} // namespace tessera::backends
