#include "R2vbSubdivRefinePass.h"

#include "R2vbRecording.h"
#include "tessera/gpu/Barriers.h"

#include "r2vb_cage.frag.spv.h"
#include "r2vb_subdiv_refine.vert.spv.h"

namespace tessera::backends {

namespace {

// Every stage that reads refined points: the command pass, the emulated
// draw's evaluation and its fragment shading.
constexpr VkPipelineStageFlags2 kPointReads =
    VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;

// The R2VB step for a target whose last row is partly used: the whole rows,
// then the used part of the last, so exactly `count` texels land at
// elements 0 .. count - 1 of the buffer, which holds no more.
void copyTexels(VkCommandBuffer cmd, const gpu::Image& image, uint32_t count, const gpu::Buffer& buffer) {
    const uint32_t width = image.width();
    VkBufferImageCopy regions[2]{};
    uint32_t n = 0;
    if (count / width > 0) {
        regions[n].imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        regions[n].imageExtent = {width, count / width, 1};
        ++n;
    }
    if (count % width > 0) {
        regions[n].bufferOffset = VkDeviceSize(count / width) * width * 16;
        regions[n].imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        regions[n].imageOffset = {0, int32_t(count / width), 0};
        regions[n].imageExtent = {count % width, 1, 1};
        ++n;
    }
    vkCmdCopyImageToBuffer(cmd, image.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, buffer.handle(), n, regions);
}

} // namespace

R2vbSubdivRefinePass::R2vbSubdivRefinePass(gpu::Device& device) {
    const VkShaderStageFlags vertex = VK_SHADER_STAGE_VERTEX_BIT;
    mLayout = gpu::PipelineLayout(device, GpuSubdiv::refineBindings(vertex), sizeof(shader::R2vbTargetConstants),
                                  vertex, "r2vb.subdivRefine.layout");
    // The pixel shader only writes the vec4 its point carries: the cage
    // pass's does exactly that.
    gpu::GraphicsPipelineDesc desc = r2vb::pointPipeline("r2vb.subdivRefine", mLayout, r2vb_subdiv_refine_vert_spv,
                                                         r2vb_cage_frag_spv, {VK_FORMAT_R32G32B32A32_SFLOAT});
    // No vertex stream: the vertex index is the refined point.
    mPipeline = gpu::Pipeline(device, desc);
}

void R2vbSubdivRefinePass::record(gpu::FrameContext& frame, GpuSubdiv& surface, R2vbSubdivTargets& targets) {
    VkCommandBuffer cmd = frame.cmd();
    gpu::Image& image = targets.points();
    {
        gpu::PassScope pass(frame, "subdiv.refine");
        // Rewritten each frame; the last reader was the previous copy.
        gpu::transitionImage(cmd, image.handle(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                             VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_NONE,
                             VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
        gpu::Image* const attachments[1] = {&image};
        r2vb::beginPoints(cmd, attachments, targets.pointRows(), mLayout);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mPipeline.handle());
        const std::vector<VkWriteDescriptorSet> writes = surface.refineWrites(frame.slot());
        frame.device().fn().cmdPushDescriptorSet(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mLayout.handle(), 0,
                                                 uint32_t(writes.size()), writes.data());
        vkCmdDraw(cmd, surface.refinedPointCount(), 1, 0, 0);
        vkCmdEndRendering(cmd);
    }
    gpu::PassScope pass(frame, "subdiv.copyPoints");
    gpu::transitionImage(cmd, image.handle(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                         VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                         VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_COPY_BIT,
                         VK_ACCESS_2_TRANSFER_READ_BIT);
    // The previous draw of this surface may still read the points (write
    // after read).
    gpu::memoryBarrier(cmd, kPointReads, VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_COPY_BIT,
                       VK_ACCESS_2_TRANSFER_WRITE_BIT);
    copyTexels(cmd, image, surface.refinedPointCount(), surface.points());
    gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT, kPointReads,
                       VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
}

} // namespace tessera::backends
