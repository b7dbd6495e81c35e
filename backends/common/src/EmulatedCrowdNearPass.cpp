#include "common/EmulatedCrowdNearPass.h"

#include "tessera/gpu/Device.h"
#include "tessera/gpu/FrameContext.h"

#include "character.frag_crowd_texels.spv.h"
#include "crowd_near_emulated.vert.spv.h"

namespace tessera::backends {

EmulatedCrowdNearPass::EmulatedCrowdNearPass(gpu::Device& device, VkFormat colorFormat, VkFormat depthFormat,
                                             const std::string& backendName)
    : mDevice(&device), mLayout(CrowdDescriptors::layout(device, CrowdDescriptors::Mode::Texels,
                                                         VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT,
                                                         backendName + ".crowd.near.layout")) {
    gpu::GraphicsPipelineDesc desc;
    desc.name = backendName + ".crowd.near";
    desc.layout = &mLayout;
    desc.stages = {{VK_SHADER_STAGE_VERTEX_BIT, crowd_near_emulated_vert_spv},
                   {VK_SHADER_STAGE_FRAGMENT_BIT, character_frag_crowd_texels_spv}};
    // The pattern's point codes, one per vertex.
    desc.vertexBindings = {{0, sizeof(uint32_t), VK_VERTEX_INPUT_RATE_VERTEX}};
    desc.vertexAttributes = {{0, 0, VK_FORMAT_R32_UINT, 0}};
    // The tessellator's ccw domain order comes out clockwise on screen, as
    // hulldomain's near tier and the character passes.
    desc.cullMode = VK_CULL_MODE_BACK_BIT;
    desc.frontFace = VK_FRONT_FACE_CLOCKWISE;
    desc.colorFormats = {colorFormat};
    desc.depthFormat = depthFormat;
    mPipeline = gpu::Pipeline(device, desc);
}

void EmulatedCrowdNearPass::record(gpu::FrameContext& frame, GpuCrowd& crowd, CrowdDescriptors& descriptors) {
    VkCommandBuffer cmd = frame.cmd();
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mPipeline.handle());
    gpu::PassScope pass(frame, "crowd.near");
    const VkBuffer codes = crowd.patternCodes().handle();
    const VkDeviceSize zero = 0;
    vkCmdBindVertexBuffers(cmd, 0, 1, &codes, &zero);
    vkCmdBindIndexBuffer(cmd, crowd.patternIndices().handle(), 0, VK_INDEX_TYPE_UINT32);
    const uint32_t slots = crowd.nearSlots();
    const uint32_t stride = TS_CROWD_NEAR_COMMAND_WORDS * sizeof(uint32_t);
    for (uint32_t c = 0; c < crowd.creatures().size(); ++c) {
        const auto writes = descriptors.writes(c);
        mDevice->fn().cmdPushDescriptorSet(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mLayout.handle(), 0,
                                           uint32_t(writes.size()), writes.data());
        const VkDeviceSize offset = VkDeviceSize(shader::tsCrowdNearCommandBase(c, 0, slots)) * sizeof(uint32_t);
        vkCmdDrawIndexedIndirect(cmd, crowd.nearCommands().handle(), offset, slots, stride);
    }
}

} // namespace tessera::backends
