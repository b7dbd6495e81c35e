#include "common/ComputeCharacterSkinPass.h"

#include "tessera/gpu/Barriers.h"

#include "common/CommandHelpers.h"
#include "tessera/shaders/FrameUniforms.h"
#include "tessera/gpu/FrameContext.h"

#include "character_skin.comp.spv.h"

namespace tessera::backends {

ComputeCharacterSkinPass::ComputeCharacterSkinPass(gpu::Device& device, const std::string& backendName) {
    const VkShaderStageFlags compute = VK_SHADER_STAGE_COMPUTE_BIT;
    mLayout = characterLayout(device, CharacterBindings::Skin, compute, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 0, 0,
                              backendName + ".characterSkin.layout");
    mPipeline = gpu::ComputePipeline(device, mLayout, character_skin_comp_spv, backendName + ".characterSkin");
}

void ComputeCharacterSkinPass::record(gpu::FrameContext& frame, const CharacterInstance& instance,
                                      const CharacterPushFn& push, VkPipelineStageFlags2 reader) {
    VkCommandBuffer cmd = frame.cmd();
    GpuCharacter& c = *instance.character;
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, mPipeline.handle());
    const VkDescriptorBufferInfo cage{c.vertices().handle(), 0, VK_WHOLE_SIZE};
    const VkDescriptorBufferInfo out{instance.compressed->buffer.handle(), 0, VK_WHOLE_SIZE};
    const VkWriteDescriptorSet writes[2] = {
        bufferWrite(TS_BINDING_CAGE_VERTICES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, &cage),
        bufferWrite(TS_BINDING_COMPRESSED, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, &out)};
    push(VK_PIPELINE_BIND_POINT_COMPUTE, CharacterBindings::Skin, mLayout, instance, writes);
    vkCmdDispatch(cmd, (c.vertexCount() + 63) / 64, 1, 1);
    gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                       reader, VK_ACCESS_2_SHADER_STORAGE_READ_BIT);
}

} // namespace tessera::backends
