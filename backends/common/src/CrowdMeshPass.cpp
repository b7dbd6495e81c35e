#include "common/CrowdMeshPass.h"

#include "tessera/shaders/CharacterUniforms.h"
#include "tessera/gpu/Device.h"
#include "tessera/gpu/FrameContext.h"

namespace tessera::backends {

CrowdMeshPass::CrowdMeshPass(gpu::Device& device, CrowdDescriptors::Mode mode, std::span<const uint32_t> vertex,
                             std::span<const uint32_t> fragment, VkFormat colorFormat, VkFormat depthFormat,
                             const std::string& name)
    : mDevice(&device),
      mLayout(CrowdDescriptors::layout(device, mode, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT,
                                       name + ".layout")) {
    gpu::GraphicsPipelineDesc desc;
    desc.name = name;
    desc.layout = &mLayout;
    desc.stages = {{VK_SHADER_STAGE_VERTEX_BIT, vertex}, {VK_SHADER_STAGE_FRAGMENT_BIT, fragment}};
    // The list's entries, one per instance: the only stream (vertices come
    // from the baked vertex animation by index).
    desc.vertexBindings = {{0, sizeof(shader::CrowdListEntry), VK_VERTEX_INPUT_RATE_INSTANCE}};
    desc.vertexAttributes = {{0, 0, VK_FORMAT_R32G32B32A32_UINT, 0}};
    // Back faces culled: the meshes' own glTF counter-clockwise triangles,
    // which Camera's Y-flipped projection keeps counter-clockwise in
    // Vulkan's y-down framebuffer. (The tessellated near tier winds as the
    // domain's ccw ordering makes it, which comes out clockwise.)
    desc.cullMode = VK_CULL_MODE_BACK_BIT;
    desc.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
    desc.colorFormats = {colorFormat};
    desc.depthFormat = depthFormat;
    mPipeline = gpu::Pipeline(device, desc);
}

void CrowdMeshPass::record(gpu::FrameContext& frame, GpuCrowd& crowd, CrowdDescriptors& descriptors) {
    VkCommandBuffer cmd = frame.cmd();
    static const char* const kPassNames[2] = {"crowd.middle", "crowd.far"};
    const uint32_t creatures = uint32_t(crowd.creatures().size());
    for (uint32_t tier = TS_LOD_MIDDLE; tier <= TS_LOD_FAR; ++tier) {
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mPipeline.handle());
        gpu::PassScope pass(frame, kPassNames[tier - TS_LOD_MIDDLE]);
        const VkBuffer entries = crowd.lists().handle();
        const VkDeviceSize zero = 0;
        vkCmdBindVertexBuffers(cmd, 0, 1, &entries, &zero);
        vkCmdBindIndexBuffer(cmd, crowd.indices().handle(), 0, VK_INDEX_TYPE_UINT32);
        for (uint32_t c = 0; c < creatures; ++c) {
            const auto writes = descriptors.writes(c);
            mDevice->fn().cmdPushDescriptorSet(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mLayout.handle(), 0,
                                               uint32_t(writes.size()), writes.data());
            const VkDeviceSize offset =
                VkDeviceSize(tier * TS_CROWD_MAX_CHARACTERS + c) * TS_CROWD_ARG_DRAW_WORDS * sizeof(uint32_t);
            vkCmdDrawIndexedIndirect(cmd, crowd.args().handle(), offset, 1, 0);
        }
    }
}

} // namespace tessera::backends
