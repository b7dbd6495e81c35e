#include "StreamoutCullPass.h"

#include "common/TerrainBindings.h"
#include "tessera/gpu/Barriers.h"

#include "tessera/shaders/FrameUniforms.h"
#include "StreamoutRecording.h"
#include "tessera/shaders/TerrainUniforms.h"
#include "streamout_bindings.h"

#include "streamout_cull.geom.spv.h"
#include "streamout_cull.vert.spv.h"

namespace tessera::backends {

StreamoutCullPass::StreamoutCullPass(gpu::Device& device) {
    const VkShaderStageFlags stages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_GEOMETRY_BIT;
    mLayout = terrainLayout(device, stages, {{SO_BINDING_CAGE, VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER, stages}},
                                  0, 0, "streamout.cull.layout");
    gpu::GraphicsPipelineDesc desc =
        streamout::streamOutPipelineDesc("streamout.cull", mLayout,
                                         {{VK_SHADER_STAGE_VERTEX_BIT, streamout_cull_vert_spv},
                                          {VK_SHADER_STAGE_GEOMETRY_BIT, streamout_cull_geom_spv}});
    // The visible-patch stream, one point per patch.
    desc.vertexBindings = {{0, sizeof(uint32_t), VK_VERTEX_INPUT_RATE_VERTEX}};
    desc.vertexAttributes = {{0, 0, VK_FORMAT_R32_UINT, 0}};
    mPipeline = gpu::Pipeline(device, desc);
}

void StreamoutCullPass::record(const StreamoutPassInputs& in, std::span<const uint32_t> visiblePatches) {
    gpu::PassScope pass(in.frame, "streamout.cull");
    VkCommandBuffer cmd = in.frame.cmd();
    const auto& fn = in.frame.device().fn();
    const StreamoutBuffers::Slot& buffers = in.buffers;

    streamout::beginStreamOut(cmd);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mPipeline.handle());
    const VkBufferView cage = buffers.cageView.handle();
    const VkWriteDescriptorSet writes[1] = {texelWrite(SO_BINDING_CAGE, &cage)};
    in.pushBindings(VK_PIPELINE_BIND_POINT_GRAPHICS, mLayout, writes);
    const VkBuffer patches = in.terrain.writeVisiblePatches(in.frame.slot(), visiblePatches).handle();
    const VkDeviceSize zero = 0;
    vkCmdBindVertexBuffers(cmd, 0, 1, &patches, &zero);
    const VkBuffer survivors = buffers.survivors.handle();
    const VkDeviceSize size = buffers.survivors.size();
    fn.cmdBindTransformFeedbackBuffers(cmd, 0, 1, &survivors, &zero, &size);
    // No counter to resume from: the stream starts at the buffer's start.
    fn.cmdBeginTransformFeedback(cmd, 0, 0, nullptr, nullptr);
    vkCmdDraw(cmd, static_cast<uint32_t>(visiblePatches.size()), 1, 0, 0);
    const VkBuffer counter = buffers.counter.handle();
    fn.cmdEndTransformFeedback(cmd, 0, 1, &counter, &zero);
    streamout::endStreamOut(cmd);

    gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_TRANSFORM_FEEDBACK_BIT_EXT,
                       VK_ACCESS_2_TRANSFORM_FEEDBACK_WRITE_BIT_EXT |
                       VK_ACCESS_2_TRANSFORM_FEEDBACK_COUNTER_WRITE_BIT_EXT,
                       VK_PIPELINE_STAGE_2_VERTEX_ATTRIBUTE_INPUT_BIT | VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT,
                       VK_ACCESS_2_VERTEX_ATTRIBUTE_READ_BIT | VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT |
                       VK_ACCESS_2_TRANSFORM_FEEDBACK_COUNTER_READ_BIT_EXT);
}

} // namespace tessera::backends
