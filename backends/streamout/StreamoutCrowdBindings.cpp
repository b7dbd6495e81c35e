#include "StreamoutCrowdBindings.h"

#include "common/CommandHelpers.h"
#include "tessera/shaders/CrowdInstance.h"
#include "tessera/gpu/Device.h"

namespace tessera::backends {
namespace {

constexpr VkShaderStageFlags kStages =
    VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_GEOMETRY_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
constexpr VkShaderStageFlags kPushStages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_GEOMETRY_BIT;
constexpr uint32_t kPushBytes = 4 * sizeof(uint32_t);

// The texel buffers, in the order the constructor fills them. The cage
// texels take the crowd vertices' binding and the state target the LOD
// state's: the same data as hulldomain's storage buffers there.
constexpr uint32_t kTexelBindings[] = {TS_BINDING_CROWD_INSTANCES, TS_BINDING_CROWD_BAKED, TS_BINDING_CROWD_CLIPS,
                                       TS_BINDING_CROWD_SLOTS, TS_BINDING_CROWD_VERTICES, TS_BINDING_CROWD_OCCLUDERS};

} // namespace

gpu::PipelineLayout StreamoutCrowdBindings::layout(gpu::Device& device) {
    std::vector<gpu::BindingDesc> bindings = {{TS_BINDING_CROWD, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, kStages},
                                              {TS_BINDING_CROWD_STATE, VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, kStages}};
    for (uint32_t binding : kTexelBindings)
        bindings.push_back({binding, VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER, kStages});
    return gpu::PipelineLayout(device, bindings, kPushBytes, kPushStages, "streamout.crowd.layout");
}

StreamoutCrowdBindings::StreamoutCrowdBindings(GpuCrowd& crowd, StreamoutCrowdResources& resources, uint32_t slot,
                                               const gpu::UniformSlice& uniforms)
    : mUniforms(uniforms.descriptor()), mTexels{crowd.instancesView(slot), crowd.bakedView(), crowd.clipsView(),
                                                crowd.nearSlotsView(), resources.cagesView(), crowd.occludersView(slot)},
      mState{VK_NULL_HANDLE, resources.stateRead().view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL} {
    mWrites[0] = bufferWrite(TS_BINDING_CROWD, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, &mUniforms);
    VkWriteDescriptorSet& state = mWrites[1];
    state = VkWriteDescriptorSet{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    state.dstBinding = TS_BINDING_CROWD_STATE;
    state.descriptorCount = 1;
    state.descriptorType = VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE;
    state.pImageInfo = &mState;
    for (size_t i = 0; i < kTexels; ++i) mWrites[2 + i] = texelWrite(kTexelBindings[i], &mTexels[i]);
}

void StreamoutCrowdBindings::push(gpu::FrameContext& frame, const gpu::PipelineLayout& layout, uint32_t tier,
                                  uint32_t creature, uint32_t cageBase) const {
    VkCommandBuffer cmd = frame.cmd();
    frame.device().fn().cmdPushDescriptorSet(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout.handle(), 0,
                                             uint32_t(mWrites.size()), mWrites.data());
    const uint32_t constants[4] = {tier, creature, cageBase, 0};
    vkCmdPushConstants(cmd, layout.handle(), kPushStages, 0, kPushBytes, constants);
}

} // namespace tessera::backends
