#include "StreamoutCagePass.h"

#include "common/TerrainBindings.h"
#include "tessera/gpu/Barriers.h"

#include "tessera/shaders/FrameUniforms.h"
#include "StreamoutRecording.h"
#include "tessera/shaders/TerrainUniforms.h"
#include "tessera/shaders/TessFactors.h"

#include "streamout_cage.vert.spv.h"

namespace tessera::backends {

StreamoutCagePass::StreamoutCagePass(gpu::Device& device) {
    const VkShaderStageFlags vertex = VK_SHADER_STAGE_VERTEX_BIT;
    mLayout = terrainLayout(device, vertex, {{TS_BINDING_TESS, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, vertex}},
                                  0, 0, "streamout.cage.layout");
    gpu::GraphicsPipelineDesc desc = streamout::streamOutPipelineDesc(
        "streamout.cage", mLayout, {{VK_SHADER_STAGE_VERTEX_BIT, streamout_cage_vert_spv}});
    // No vertex buffer: the vertex ID is the grid point.
    mPipeline = gpu::Pipeline(device, desc);
}

void StreamoutCagePass::record(const StreamoutPassInputs& in) {
    gpu::PassScope pass(in.frame, "streamout.cage");
    VkCommandBuffer cmd = in.frame.cmd();
    const auto& fn = in.frame.device().fn();
    const StreamoutBuffers::Slot& buffers = in.buffers;
    const uint32_t gridVertices = (in.terrain.patchesPerSide() + 1) * (in.terrain.patchesPerSide() + 1);

    streamout::beginStreamOut(cmd);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mPipeline.handle());
    const VkDescriptorBufferInfo tess = in.tessUniforms.descriptor();
    const VkWriteDescriptorSet writes[1] = {
        bufferWrite(TS_BINDING_TESS, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, &tess)};
    in.pushBindings(VK_PIPELINE_BIND_POINT_GRAPHICS, mLayout, writes);
    const VkBuffer cage = buffers.cage.handle();
    const VkDeviceSize offset = 0;
    const VkDeviceSize size = VkDeviceSize(gridVertices) * 4 * sizeof(float); // RGBA32F texels
    fn.cmdBindTransformFeedbackBuffers(cmd, 0, 1, &cage, &offset, &size);
    fn.cmdBeginTransformFeedback(cmd, 0, 0, nullptr, nullptr);
    vkCmdDraw(cmd, gridVertices, 1, 0, 0);
    fn.cmdEndTransformFeedback(cmd, 0, 0, nullptr, nullptr);
    streamout::endStreamOut(cmd);

    gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_TRANSFORM_FEEDBACK_BIT_EXT,
                       VK_ACCESS_2_TRANSFORM_FEEDBACK_WRITE_BIT_EXT,
                       VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_GEOMETRY_SHADER_BIT,
                       VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
}

} // namespace tessera::backends
