#include "R2vbSubdivCommandPass.h"

#include "R2vbRecording.h"
#include "tessera/shaders/TessPattern.h"
#include "tessera/gpu/Barriers.h"

#include "r2vb_commands.frag.spv.h"
#include "r2vb_subdiv_commands.vert.spv.h"

#include <vector>

namespace tessera::backends {

namespace {
constexpr VkDeviceSize kVec4Bytes = 16;
constexpr uint32_t kOuterTarget = 0, kInnerTarget = 1, kFirstCommandTarget = 2;
} // namespace

R2vbSubdivCommandPass::R2vbSubdivCommandPass(gpu::Device& device) {
    const VkShaderStageFlags vertex = VK_SHADER_STAGE_VERTEX_BIT;
    std::vector<gpu::BindingDesc> bindings = GpuSubdiv::levelBindings(vertex);
    bindings.push_back({TS_BINDING_EMU_KEYS, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, vertex});
    mLayout = gpu::PipelineLayout(device, bindings, sizeof(shader::R2vbTargetConstants), vertex,
                                  "r2vb.subdivCommands.layout");
    std::vector<VkFormat> formats(R2VB_COMMAND_TARGETS, VK_FORMAT_R32G32B32A32_UINT);
    formats[kOuterTarget] = VK_FORMAT_R32G32B32A32_SFLOAT;
    formats[kInnerTarget] = VK_FORMAT_R32G32B32A32_SFLOAT;
    // No vertex stream: the vertex index is the domain.
    gpu::GraphicsPipelineDesc desc = r2vb::pointPipeline("r2vb.subdivCommands", mLayout, r2vb_subdiv_commands_vert_spv,
                                                         r2vb_commands_frag_spv, std::move(formats));
    mPipeline = gpu::Pipeline(device, desc);
}

EmulatedDrawSource R2vbSubdivCommandPass::record(gpu::FrameContext& frame, GpuSubdiv& surface,
                                                 R2vbSubdivTargets& targets, const gpu::UniformSlice& uniforms,
                                                 const gpu::Buffer& keyTable) {
    VkCommandBuffer cmd = frame.cmd();
    auto& images = targets.recordTargets();
    {
        gpu::PassScope pass(frame, "subdiv.commands");
        // Rewritten each frame; the last reader was the previous copy.
        std::array<gpu::Image*, R2VB_COMMAND_TARGETS> attachments;
        for (uint32_t i = 0; i < R2VB_COMMAND_TARGETS; ++i) {
            gpu::transitionImage(cmd, images[i].handle(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                                 VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_COPY_BIT,
                                 VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                                 VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
            attachments[i] = &images[i];
        }
        // Whole rows are cleared, so the records past the last domain hold
        // zero commands, which draw nothing.
        r2vb::beginPoints(cmd, attachments, targets.recordRows(), mLayout);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mPipeline.handle());
        std::vector<VkWriteDescriptorSet> writes = surface.levelWrites(uniforms);
        const VkDescriptorBufferInfo keys{keyTable.handle(), 0, VK_WHOLE_SIZE};
        writes.push_back(bufferWrite(TS_BINDING_EMU_KEYS, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, &keys));
        frame.device().fn().cmdPushDescriptorSet(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mLayout.handle(), 0,
                                                 uint32_t(writes.size()), writes.data());
        vkCmdDraw(cmd, surface.domainCount(), 1, 0, 0);
        vkCmdEndRendering(cmd);
    }
    gpu::PassScope pass(frame, "subdiv.copyRecords");
    copyToBuffers(cmd, targets);
    return targets.source();
}

void R2vbSubdivCommandPass::copyToBuffers(VkCommandBuffer cmd, R2vbSubdivTargets& targets) {
    auto& images = targets.recordTargets();
    for (gpu::Image& image : images)
        gpu::transitionImage(cmd, image.handle(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                             VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                             VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_COPY_BIT,
                             VK_ACCESS_2_TRANSFER_READ_BIT);
    // The previous draw of this surface may still read the buffers (write
    // after read).
    gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT,
                       VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
    // The contract's layout: texel r outer levels, texel capacity + r inner
    // levels and domain; command c of every record in the c-th block.
    const uint32_t rows = targets.recordRows();
    const VkDeviceSize block = VkDeviceSize(targets.capacity()) * kVec4Bytes;
    r2vb::copyRows(cmd, images[kOuterTarget], rows, targets.records(), 0);
    r2vb::copyRows(cmd, images[kInnerTarget], rows, targets.records(), block);
    for (uint32_t piece = 0; piece < TS_EMU_PIECES; ++piece)
        r2vb::copyRows(cmd, images[kFirstCommandTarget + piece], rows, targets.commands(), piece * block);
    gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                       VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT,
                       VK_ACCESS_2_SHADER_SAMPLED_READ_BIT | VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT);
}

} // namespace tessera::backends
