#include "common/CrowdMeshPass.h"

#include "tessera/shaders/CharacterUniforms.h"

namespace tessera::backends {

// The list's entries, one per instance, are the only stream (vertices come
// from the baked vertex animation by index). Back faces culled: the meshes'
// own glTF counter-clockwise triangles, which Camera's Y-flipped projection
// keeps counter-clockwise in Vulkan's y-down framebuffer. (The tessellated
// near tier winds as the domain's ccw ordering makes it, which comes out
// clockwise.)
CrowdMeshPass::CrowdMeshPass(gpu::Device& device, CrowdDescriptors::Mode mode, std::span<const uint32_t> vertex,
                             std::span<const uint32_t> fragment, VkFormat colorFormat, VkFormat depthFormat,
                             const std::string& name, std::span<const uint32_t> casterVertex)
    : mPipeline(device, mode, vertex, fragment,
                {sizeof(shader::CrowdListEntry), VK_VERTEX_INPUT_RATE_INSTANCE, VK_FORMAT_R32G32B32A32_UINT},
                VK_FRONT_FACE_COUNTER_CLOCKWISE, VK_CULL_MODE_BACK_BIT, colorFormat, depthFormat, name, casterVertex) {}

namespace {

// The indirect draw of list (tier, creature).
void drawList(VkCommandBuffer cmd, GpuCrowd& crowd, uint32_t tier, uint32_t creature) {
    const VkDeviceSize offset =
        VkDeviceSize(tier * TS_CROWD_MAX_CHARACTERS + creature) * TS_CROWD_ARG_DRAW_WORDS * sizeof(uint32_t);
    vkCmdDrawIndexedIndirect(cmd, crowd.args().handle(), offset, 1, 0);
}

} // namespace

void CrowdMeshPass::record(gpu::FrameContext& frame, GpuCrowd& crowd, CrowdDescriptors& descriptors) {
    static const char* const kPassNames[2] = {"crowd.middle", "crowd.far"};
    for (uint32_t tier = TS_LOD_MIDDLE; tier <= TS_LOD_FAR; ++tier)
        mPipeline.record(frame, kPassNames[tier - TS_LOD_MIDDLE], crowd, descriptors, crowd.lists().handle(),
                         crowd.indices().handle(),
                         [&](VkCommandBuffer cmd, uint32_t c) { drawList(cmd, crowd, tier, c); });
}

void CrowdMeshPass::recordShadow(gpu::FrameContext& frame, GpuCrowd& crowd, CrowdDescriptors& descriptors,
                                 const shader::ShadowCasterPush& caster) {
    // Both tiers cast the far mesh simplified for depth (GpuCrowd::casterArgs,
    // copied in by recordCasterArgs; the caster variant of crowd_mesh.vert
    // reads the far mesh's vertices for either list).
    for (uint32_t tier = TS_LOD_MIDDLE; tier <= TS_LOD_FAR; ++tier)
        mPipeline.recordShadow(frame, crowd, descriptors, crowd.lists().handle(), crowd.indices().handle(), caster,
                               [&](VkCommandBuffer cmd, uint32_t c) {
                                   vkCmdDrawIndexedIndirect(cmd, crowd.casterArgs().handle(),
                                                            GpuCrowd::casterArgsOffset(tier, c), 1, 0);
                               });
}

} // namespace tessera::backends
