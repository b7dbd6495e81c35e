#include "R2vbCommandPass.h"

#include "common/TerrainBindings.h"
#include "tessera/shaders/FrameUniforms.h"
#include "tessera/shaders/TerrainUniforms.h"
#include "tessera/shaders/TessFactors.h"
#include "tessera/shaders/TessPattern.h"
#include "tessera/gpu/Barriers.h"

#include "r2vb_commands.frag.spv.h"
#include "r2vb_commands.vert.spv.h"

#include <array>

namespace tessera::backends {

namespace {

constexpr VkDeviceSize kVec4Bytes = 16;

} // namespace

R2vbCommandPass::R2vbCommandPass(gpu::Device& device) {
    const VkShaderStageFlags vertex = VK_SHADER_STAGE_VERTEX_BIT;
    mLayout = terrainLayout(device, vertex,
                            {{TS_BINDING_TESS, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, vertex},
                             {TS_BINDING_PATCH_ERROR, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, vertex},
                             {TS_BINDING_EMU_KEYS, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, vertex}},
                            sizeof(shader::R2vbTargetConstants), vertex, "r2vb.commands.layout");
    std::vector<VkFormat> formats(R2VB_COMMAND_TARGETS, VK_FORMAT_R32G32B32A32_UINT);
    formats[R2vbTargets::kOuterTarget] = VK_FORMAT_R32G32B32A32_SFLOAT;
    formats[R2vbTargets::kInnerTarget] = VK_FORMAT_R32G32B32A32_SFLOAT;
    gpu::GraphicsPipelineDesc desc = r2vb::pointPipeline("r2vb.commands", mLayout, r2vb_commands_vert_spv,
                                                         r2vb_commands_frag_spv, std::move(formats));
    // One point per record: binding 0 is the factor target re-read as a
    // vertex buffer (R2VB, the paper's stream 1), binding 1 the visible patches.
    desc.vertexBindings = {{0, 4 * sizeof(float), VK_VERTEX_INPUT_RATE_VERTEX},
                           {1, sizeof(uint32_t), VK_VERTEX_INPUT_RATE_VERTEX}};
    desc.vertexAttributes = {{0, 0, VK_FORMAT_R32G32B32A32_SFLOAT, 0}, {1, 1, VK_FORMAT_R32_UINT, 0}};
    mPipeline = gpu::Pipeline(device, desc);
}

uint32_t R2vbCommandPass::record(gpu::FrameContext& frame, R2vbTargets& targets, const gpu::Buffer& patchStream,
                                 uint32_t patches, const gpu::Buffer& patchErrors, const gpu::Buffer& keyTable,
                                 const gpu::UniformSlice& tessUniforms, const PushTerrainBindings& pushBindings) {
    VkCommandBuffer cmd = frame.cmd();
    auto& images = targets.recordTargets();
    const uint32_t rows = R2vbTargets::recordRows(patches);
    {
        gpu::PassScope pass(frame, "r2vb.commands");
        // Rewritten each frame; the last reader was an earlier frame's copy.
        std::array<VkImageMemoryBarrier2, R2VB_COMMAND_TARGETS> toTarget;
        std::array<gpu::Image*, R2VB_COMMAND_TARGETS> attachments;
        for (uint32_t i = 0; i < R2VB_COMMAND_TARGETS; ++i) {
            toTarget[i] =
                gpu::imageBarrier(images[i], VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                                   VK_PIPELINE_STAGE_2_COPY_BIT, 0, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                                   VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
            attachments[i] = &images[i];
        }
        gpu::pipelineBarrier(cmd, toTarget);

        // Whole rows are cleared, so the records past the last visible patch
        // hold zero commands, which draw nothing.
        r2vb::beginPoints(cmd, attachments, rows, mLayout);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mPipeline.handle());
        const VkDescriptorBufferInfo tess = tessUniforms.descriptor();
        const VkDescriptorBufferInfo errors{patchErrors.handle(), 0, VK_WHOLE_SIZE};
        const VkDescriptorBufferInfo keys{keyTable.handle(), 0, VK_WHOLE_SIZE};
        const VkWriteDescriptorSet writes[3] = {
            bufferWrite(TS_BINDING_TESS, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, &tess),
            bufferWrite(TS_BINDING_PATCH_ERROR, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, &errors),
            bufferWrite(TS_BINDING_EMU_KEYS, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, &keys)};
        pushBindings(VK_PIPELINE_BIND_POINT_GRAPHICS, mLayout, writes);
        const VkBuffer streams[2] = {targets.factorStream().handle(), patchStream.handle()};
        const VkDeviceSize offsets[2] = {0, 0};
        vkCmdBindVertexBuffers(cmd, 0, 2, streams, offsets);
        vkCmdDraw(cmd, patches, 1, 0, 0);
        vkCmdEndRendering(cmd);
    }
    const uint32_t capacity = rows * R2VB_RECORD_WIDTH;
    gpu::PassScope pass(frame, "r2vb.copyRecords");
    copyToBuffers(cmd, targets, rows, capacity);
    return capacity;
}

void R2vbCommandPass::copyToBuffers(VkCommandBuffer cmd, R2vbTargets& targets, uint32_t rows, uint32_t capacity) {
    auto& images = targets.recordTargets();
    gpu::Buffer& records = targets.records();
    gpu::Buffer& commands = targets.commands();
    std::array<VkImageMemoryBarrier2, R2VB_COMMAND_TARGETS> toCopy;
    for (uint32_t i = 0; i < R2VB_COMMAND_TARGETS; ++i)
        toCopy[i] = gpu::imageBarrier(
            images[i], VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
            VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
            VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
    // The buffers' last readers were an earlier frame's emulated draw.
    const VkBufferMemoryBarrier2 toWrite[2] = {
        gpu::bufferBarrier(records, VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT, 0, VK_PIPELINE_STAGE_2_COPY_BIT,
                            VK_ACCESS_2_TRANSFER_WRITE_BIT),
        gpu::bufferBarrier(commands, VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT, 0, VK_PIPELINE_STAGE_2_COPY_BIT,
                            VK_ACCESS_2_TRANSFER_WRITE_BIT)};
    gpu::pipelineBarrier(cmd, toCopy, toWrite);

    // The contract's layout: texel r outer levels, texel capacity + r inner
    // levels and patch; command c of every record in the c-th block of capacity.
    const VkDeviceSize block = capacity * kVec4Bytes;
    r2vb::copyRows(cmd, images[R2vbTargets::kOuterTarget], rows, records, 0);
    r2vb::copyRows(cmd, images[R2vbTargets::kInnerTarget], rows, records, block);
    for (uint32_t piece = 0; piece < TS_EMU_PIECES; ++piece)
        r2vb::copyRows(cmd, images[R2vbTargets::kFirstCommandTarget + piece], rows, commands, piece * block);

    const VkBufferMemoryBarrier2 toRead[2] = {
        gpu::bufferBarrier(records, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                            VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT),
        gpu::bufferBarrier(commands, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                            VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT, VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT)};
    gpu::pipelineBarrier(cmd, {}, toRead);
}

} // namespace tessera::backends
