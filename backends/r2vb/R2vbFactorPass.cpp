#include "R2vbFactorPass.h"

#include "common/TerrainBindings.h"
#include "tessera/shaders/FrameUniforms.h"
#include "tessera/shaders/TerrainUniforms.h"
#include "tessera/shaders/TessFactors.h"
#include "tessera/gpu/Barriers.h"

#include "r2vb_factors.frag.spv.h"
#include "r2vb_factors.vert.spv.h"

namespace tessera::backends {

R2vbFactorPass::R2vbFactorPass(gpu::Device& device) {
    const VkShaderStageFlags vertex = VK_SHADER_STAGE_VERTEX_BIT;
    mLayout = terrainLayout(device, vertex,
                            {{TS_BINDING_TESS, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, vertex},
                             {TS_BINDING_EDGE_ERROR, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, vertex},
                             {R2VB_BINDING_CAGE, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, vertex}},
                            sizeof(shader::R2vbTargetConstants), vertex, "r2vb.factors.layout");
    gpu::GraphicsPipelineDesc desc = r2vb::pointPipeline("r2vb.factors", mLayout, r2vb_factors_vert_spv,
                                                         r2vb_factors_frag_spv, {VK_FORMAT_R32_SFLOAT});
    // Four points (edges) per instance; the instance's patch from the
    // visible-patch stream, for the edge's detail error.
    desc.vertexBindings = {{0, sizeof(uint32_t), VK_VERTEX_INPUT_RATE_INSTANCE}};
    desc.vertexAttributes = {{0, 0, VK_FORMAT_R32_UINT, 0}};
    mPipeline = gpu::Pipeline(device, desc);
    mCageSampler = gpu::Sampler(device, VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, "r2vb.cage.sampler");
}

void R2vbFactorPass::record(gpu::FrameContext& frame, R2vbTargets& targets, const gpu::Buffer& patchStream,
                            uint32_t patches, const gpu::Buffer& edgeErrors, const gpu::UniformSlice& tessUniforms,
                            const PushTerrainBindings& pushBindings) {
    VkCommandBuffer cmd = frame.cmd();
    {
        gpu::PassScope pass(frame, "r2vb.factors");
        gpu::Image& factors = targets.factors();
        // Rewritten each frame; the last reader was an earlier frame's copy.
        const VkImageMemoryBarrier2 toTarget = gpu::imageBarrier(
            factors, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_COPY_BIT,
            0, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
        gpu::pipelineBarrier(cmd, {&toTarget, 1});

        gpu::Image* const attachments[1] = {&factors};
        r2vb::beginPoints(cmd, attachments, R2vbTargets::cageRows(patches), mLayout);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mPipeline.handle());
        const VkDescriptorBufferInfo tess = tessUniforms.descriptor();
        const VkDescriptorBufferInfo errors{edgeErrors.handle(), 0, VK_WHOLE_SIZE};
        const VkDescriptorImageInfo cage{mCageSampler.handle(), targets.cage().view(),
                                         VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
        VkWriteDescriptorSet writes[3] = {
            bufferWrite(TS_BINDING_TESS, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, &tess),
            bufferWrite(TS_BINDING_EDGE_ERROR, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, &errors),
            bufferWrite(R2VB_BINDING_CAGE, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, nullptr)};
        writes[2].pImageInfo = &cage;
        pushBindings(VK_PIPELINE_BIND_POINT_GRAPHICS, mLayout, writes);
        const VkBuffer stream = patchStream.handle();
        const VkDeviceSize offset = 0;
        vkCmdBindVertexBuffers(cmd, 0, 1, &stream, &offset);
        vkCmdDraw(cmd, 4, patches, 0, 0);
        vkCmdEndRendering(cmd);
    }
    gpu::PassScope pass(frame, "r2vb.copyFactors");
    copyToStream(cmd, targets, patches);
}

void R2vbFactorPass::copyToStream(VkCommandBuffer cmd, R2vbTargets& targets, uint32_t patches) {
    gpu::Image& factors = targets.factors();
    gpu::Buffer& stream = targets.factorStream();
    const VkImageMemoryBarrier2 toCopy =
        gpu::imageBarrier(factors, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                           VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                           VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
    // The stream's last reader was an earlier command pass.
    const VkBufferMemoryBarrier2 toWrite =
        gpu::bufferBarrier(stream, VK_PIPELINE_STAGE_2_VERTEX_ATTRIBUTE_INPUT_BIT, 0, VK_PIPELINE_STAGE_2_COPY_BIT,
                            VK_ACCESS_2_TRANSFER_WRITE_BIT);
    gpu::pipelineBarrier(cmd, {&toCopy, 1}, {&toWrite, 1});
    // Four levels per patch, one row-major texel each: element i of the
    // buffer is texel i, so patch slot s's outer levels are the vec4 at s * 16.
    r2vb::copyRows(cmd, factors, R2vbTargets::cageRows(patches), stream, 0);
    const VkBufferMemoryBarrier2 toRead =
        gpu::bufferBarrier(stream, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                            VK_PIPELINE_STAGE_2_VERTEX_ATTRIBUTE_INPUT_BIT, VK_ACCESS_2_VERTEX_ATTRIBUTE_READ_BIT);
    gpu::pipelineBarrier(cmd, {}, {&toRead, 1});
}

} // namespace tessera::backends
