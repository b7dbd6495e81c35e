#include "R2vbCagePass.h"

#include "common/TerrainBindings.h"
#include "tessera/shaders/FrameUniforms.h"
#include "tessera/shaders/TerrainUniforms.h"
#include "tessera/shaders/TessFactors.h"
#include "tessera/gpu/Barriers.h"

#include "r2vb_cage.frag.spv.h"
#include "r2vb_cage.vert.spv.h"

namespace tessera::backends {

R2vbCagePass::R2vbCagePass(gpu::Device& device) {
    const VkShaderStageFlags vertex = VK_SHADER_STAGE_VERTEX_BIT;
    mLayout = terrainLayout(device, vertex, {{TS_BINDING_TESS, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, vertex}},
                                  sizeof(shader::R2vbTargetConstants), vertex, "r2vb.cage.layout");
    gpu::GraphicsPipelineDesc desc = r2vb::pointPipeline("r2vb.cage", mLayout, r2vb_cage_vert_spv, r2vb_cage_frag_spv,
                                                         {VK_FORMAT_R32G32B32A32_SFLOAT});
    // Four points (corners) per instance; the instance's patch from the
    // visible-patch stream.
    desc.vertexBindings = {{0, sizeof(uint32_t), VK_VERTEX_INPUT_RATE_INSTANCE}};
    desc.vertexAttributes = {{0, 0, VK_FORMAT_R32_UINT, 0}};
    mPipeline = gpu::Pipeline(device, desc);
}

void R2vbCagePass::record(gpu::FrameContext& frame, R2vbTargets& targets, const gpu::Buffer& patchStream,
                          uint32_t patches, const gpu::UniformSlice& tessUniforms,
                          const PushTerrainBindings& pushBindings) {
    gpu::PassScope pass(frame, "r2vb.cage");
    VkCommandBuffer cmd = frame.cmd();
    gpu::Image& cage = targets.cage();
    // The cage's contents are rewritten each frame; the last reader was the
    // factor pass of an earlier frame.
    const VkImageMemoryBarrier2 toTarget =
        gpu::imageBarrier(cage, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                           VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT, 0, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                           VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
    gpu::pipelineBarrier(cmd, {&toTarget, 1});

    gpu::Image* const attachments[1] = {&cage};
    r2vb::beginPoints(cmd, attachments, R2vbTargets::cageRows(patches), mLayout);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mPipeline.handle());
    const VkDescriptorBufferInfo tess = tessUniforms.descriptor();
    const VkWriteDescriptorSet writes[1] = {
        bufferWrite(TS_BINDING_TESS, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, &tess)};
    pushBindings(VK_PIPELINE_BIND_POINT_GRAPHICS, mLayout, writes);
    const VkBuffer stream = patchStream.handle();
    const VkDeviceSize offset = 0;
    vkCmdBindVertexBuffers(cmd, 0, 1, &stream, &offset);
    vkCmdDraw(cmd, 4, patches, 0, 0);
    vkCmdEndRendering(cmd);

    const VkImageMemoryBarrier2 toFetch =
        gpu::imageBarrier(cage, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                           VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                           VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
    gpu::pipelineBarrier(cmd, {&toFetch, 1});
}

} // namespace tessera::backends
