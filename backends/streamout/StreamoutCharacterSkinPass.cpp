#include "StreamoutCharacterSkinPass.h"

#include "tessera/gpu/Barriers.h"

#include "tessera/shaders/FrameUniforms.h"
#include "StreamoutRecording.h"
#include "tessera/gpu/Device.h"
#include "tessera/gpu/FrameContext.h"

#include "streamout_character_skin.vert.spv.h"

namespace tessera::backends {

StreamoutCharacterSkinPass::StreamoutCharacterSkinPass(gpu::Device& device) {
    const VkShaderStageFlags vertex = VK_SHADER_STAGE_VERTEX_BIT;
    mLayout = characterLayout(device, CharacterBindings::Skin, vertex, VK_DESCRIPTOR_TYPE_MAX_ENUM, 0, 0,
                              "streamout.characterSkin.layout");
    gpu::GraphicsPipelineDesc desc = streamout::streamOutPipelineDesc(
        "streamout.characterSkin", mLayout, {{VK_SHADER_STAGE_VERTEX_BIT, streamout_character_skin_vert_spv}});
    GpuCharacter::useCageVertexStream(desc);
    mPipeline = gpu::Pipeline(device, desc);
}

void StreamoutCharacterSkinPass::record(gpu::FrameContext& frame, const CharacterInstance& instance,
                                        const CharacterPushFn& push) {
    VkCommandBuffer cmd = frame.cmd();
    const auto& fn = frame.device().fn();
    GpuCharacter& c = *instance.character;
    streamout::beginStreamOut(cmd);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mPipeline.handle());
    push(VK_PIPELINE_BIND_POINT_GRAPHICS, CharacterBindings::Skin, mLayout, instance, {});
    const VkBuffer stream = c.vertices().handle();
    const VkDeviceSize zero = 0;
    vkCmdBindVertexBuffers(cmd, 0, 1, &stream, &zero);
    const VkBuffer out = instance.compressed->buffer.handle();
    const VkDeviceSize size = VkDeviceSize(c.vertexCount()) * 16;
    fn.cmdBindTransformFeedbackBuffers(cmd, 0, 1, &out, &zero, &size);
    fn.cmdBeginTransformFeedback(cmd, 0, 0, nullptr, nullptr);
    vkCmdDraw(cmd, c.vertexCount(), 1, 0, 0);
    fn.cmdEndTransformFeedback(cmd, 0, 0, nullptr, nullptr);
    streamout::endStreamOut(cmd);
    gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_TRANSFORM_FEEDBACK_BIT_EXT, VK_ACCESS_2_TRANSFORM_FEEDBACK_WRITE_BIT_EXT,
                       VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
}

} // namespace tessera::backends
