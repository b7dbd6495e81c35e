#include "HulldomainCrowdPass.h"

#include "tessera/gpu/Device.h"

#include "character.frag_crowd.spv.h"
#include "crowd_impostor.frag.spv.h"
#include "crowd_impostor.frag_nearest.spv.h"
#include "crowd_impostor.vert.spv.h"
#include "crowd_mesh.vert.spv.h"
#include "crowd_mesh.vert_shadow.spv.h"
#include "hulldomain_character_patch.tesc_crowd.spv.h"
#include "hulldomain_character_patch.tesc_crowd_shadow.spv.h"
#include "hulldomain_character_patch.tese_crowd.spv.h"
#include "hulldomain_character_patch.tese_crowd_shadow.spv.h"
#include "hulldomain_character_patch.vert_crowd.spv.h"

namespace tessera::backends {
namespace {

constexpr VkDeviceSize kWord = sizeof(uint32_t);

VkDeviceSize listArgsOffset(uint32_t tier, uint32_t creature) {
    return VkDeviceSize(tier * TS_CROWD_MAX_CHARACTERS + creature) * TS_CROWD_ARG_DRAW_WORDS * kWord;
}

} // namespace

HulldomainCrowdPass::HulldomainCrowdPass(gpu::Device& device, VkFormat colorFormat, VkFormat depthFormat)
    : mDevice(&device) {
    // The compute passes push through a compute-only layout of their own
    // (ComputeCrowdCullPass says why).
    using Mode = CrowdDescriptors::Mode;
    mCull = ComputeCrowdCullPass(device, "hulldomain");
    mLayout = CrowdDescriptors::layout(device, Mode::Storage, VK_SHADER_STAGE_ALL_GRAPHICS, "hulldomain.crowd.layout");

    gpu::GraphicsPipelineDesc desc;
    desc.layout = &mLayout;
    // Back faces culled. The tessellated near tier's triangles wind as the
    // domain's ccw ordering makes them, which the Y-flipped projection turns
    // clockwise (as the character passes); the middle and far tiers draw the
    // meshes' own glTF counter-clockwise triangles, which stay so.
    desc.cullMode = VK_CULL_MODE_BACK_BIT;
    desc.frontFace = VK_FRONT_FACE_CLOCKWISE;
    desc.colorFormats = {colorFormat};
    desc.depthFormat = depthFormat;
    desc.name = "hulldomain.crowd.near";
    desc.stages = {{VK_SHADER_STAGE_VERTEX_BIT, hulldomain_character_patch_vert_crowd_spv},
                   {VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT, hulldomain_character_patch_tesc_crowd_spv},
                   {VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT, hulldomain_character_patch_tese_crowd_spv},
                   {VK_SHADER_STAGE_FRAGMENT_BIT, character_frag_crowd_spv}};
    desc.topology = VK_PRIMITIVE_TOPOLOGY_PATCH_LIST;
    desc.patchControlPoints = 3;
    mNear = gpu::Pipeline(device, desc);
    const VkShaderStageFlags graphics = VK_SHADER_STAGE_ALL_GRAPHICS;
    mNearShadow = ShadowCasterPipeline(
        device, desc,
        CrowdDescriptors::layout(device, Mode::Storage, graphics, "hulldomain.crowd.near.shadow.layout", {},
                                 ShadowCasterPipeline::kPushBytes, graphics),
        graphics, {{VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT, hulldomain_character_patch_tesc_crowd_shadow_spv},
                   {VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT, hulldomain_character_patch_tese_crowd_shadow_spv}});
    mMesh = CrowdMeshPass(device, Mode::Storage, crowd_mesh_vert_spv, character_frag_crowd_spv, colorFormat, depthFormat,
                          "hulldomain.crowd.mesh", crowd_mesh_vert_shadow_spv);
    mImpostor = CrowdImpostorPass(device, Mode::Storage, crowd_impostor_vert_spv,
                                  crowdImpostorFragment(device, crowd_impostor_frag_spv, crowd_impostor_frag_nearest_spv),
                                  colorFormat, depthFormat, "hulldomain.crowd.impostor");
}

void HulldomainCrowdPass::recordCompute(gpu::FrameContext& frame, GpuCrowd& crowd, CrowdDescriptors& descriptors,
                                        uint32_t instanceCount) {
    mCull.record(frame, crowd, descriptors, instanceCount, VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT);
}

void HulldomainCrowdPass::recordDraws(gpu::FrameContext& frame, GpuCrowd& crowd, CrowdDescriptors& descriptors) {
    VkCommandBuffer cmd = frame.cmd();
    {
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mNear.handle());
        gpu::PassScope pass(frame, "crowd.near");
        drawNear(cmd, mLayout, crowd, descriptors);
    }
    mMesh.record(frame, crowd, descriptors);
    mImpostor.record(frame, crowd, descriptors);
}

void HulldomainCrowdPass::recordShadow(gpu::FrameContext& frame, GpuCrowd& crowd, CrowdDescriptors& descriptors,
                                       const shader::ShadowCasterPush& caster) {
    mNearShadow.bind(frame.cmd(), caster);
    drawNear(frame.cmd(), mNearShadow.layout(), crowd, descriptors);
    // The impostor tier casts none (CrowdImpostorPass.h).
    mMesh.recordShadow(frame, crowd, descriptors, caster);
}

void HulldomainCrowdPass::drawNear(VkCommandBuffer cmd, const gpu::PipelineLayout& layout, GpuCrowd& crowd,
                                   CrowdDescriptors& descriptors) {
    vkCmdBindIndexBuffer(cmd, crowd.indices().handle(), 0, VK_INDEX_TYPE_UINT32);
    for (uint32_t c = 0; c < crowd.creatures().size(); ++c) {
        const auto writes = descriptors.writes(c);
        mDevice->fn().cmdPushDescriptorSet(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout.handle(), 0,
                                           uint32_t(writes.size()), writes.data());
        vkCmdDrawIndexedIndirect(cmd, crowd.args().handle(), listArgsOffset(TS_LOD_NEAR, c), 1, 0);
    }
}

} // namespace tessera::backends
