#include "common/EmulatedCrowdNearPass.h"

#include "character.frag_crowd_texels.spv.h"
#include "crowd_near_emulated.vert.spv.h"
#include "crowd_near_emulated.vert_shadow.spv.h"

namespace tessera::backends {

// The pattern's point codes, one per vertex, are the stream. The
// tessellator's ccw domain order comes out clockwise on screen, as
// hulldomain's near tier and the character passes.
EmulatedCrowdNearPass::EmulatedCrowdNearPass(gpu::Device& device, VkFormat colorFormat, VkFormat depthFormat,
                                             const std::string& backendName)
    : mPipeline(device, CrowdDescriptors::Mode::Texels, crowd_near_emulated_vert_spv, character_frag_crowd_texels_spv,
                {sizeof(uint32_t), VK_VERTEX_INPUT_RATE_VERTEX, VK_FORMAT_R32_UINT}, VK_FRONT_FACE_CLOCKWISE,
                VK_CULL_MODE_BACK_BIT, colorFormat, depthFormat, backendName + ".crowd.near",
                crowd_near_emulated_vert_shadow_spv) {}

namespace {

// Creature `c`'s multi-draw over every near slot's command.
void drawSlots(VkCommandBuffer cmd, GpuCrowd& crowd, uint32_t c) {
    const uint32_t slots = crowd.nearSlots();
    const uint32_t stride = TS_CROWD_NEAR_COMMAND_WORDS * sizeof(uint32_t);
    const VkDeviceSize offset = VkDeviceSize(shader::tsCrowdNearCommandBase(c, 0, slots)) * sizeof(uint32_t);
    vkCmdDrawIndexedIndirect(cmd, crowd.nearCommands().handle(), offset, slots, stride);
}

} // namespace

void EmulatedCrowdNearPass::record(gpu::FrameContext& frame, GpuCrowd& crowd, CrowdDescriptors& descriptors) {
    mPipeline.record(frame, "crowd.near", crowd, descriptors, crowd.patternCodes().handle(),
                     crowd.patternIndices().handle(),
                     [&](VkCommandBuffer cmd, uint32_t c) { drawSlots(cmd, crowd, c); });
}

void EmulatedCrowdNearPass::recordShadow(gpu::FrameContext& frame, GpuCrowd& crowd, CrowdDescriptors& descriptors,
                                         const shader::ShadowCasterPush& caster) {
    mPipeline.recordShadow(frame, crowd, descriptors, crowd.patternCodes().handle(), crowd.patternIndices().handle(),
                           caster, [&](VkCommandBuffer cmd, uint32_t c) { drawSlots(cmd, crowd, c); });
}

} // namespace tessera::backends
