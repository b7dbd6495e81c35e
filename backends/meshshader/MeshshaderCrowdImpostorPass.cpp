#include "MeshshaderCrowdImpostorPass.h"

#include "common/CrowdImpostorPass.h"
#include "tessera/gpu/Device.h"
#include "tessera/shaders/CrowdMeshlet.h"

#include "crowd_impostor.frag.spv.h"
#include "crowd_impostor.frag_nearest.spv.h"
#include "meshshader_crowd_impostor.mesh.spv.h"

namespace tessera::backends {
namespace {

/// The mesh stage's push constants: the list's count word and first entry.
struct ImpostorPush {
    uint32_t countWord = 0, listBase = 0;
};

} // namespace

MeshshaderCrowdImpostorPass::MeshshaderCrowdImpostorPass(gpu::Device& device, VkFormat colorFormat,
                                                         VkFormat depthFormat)
    : mDevice(&device) {
    mLayout = CrowdDescriptors::layout(device, CrowdDescriptors::Mode::Storage,
                                       VK_SHADER_STAGE_MESH_BIT_EXT | VK_SHADER_STAGE_FRAGMENT_BIT,
                                       "meshshader.crowd.impostor.layout", {}, sizeof(ImpostorPush),
                                       VK_SHADER_STAGE_MESH_BIT_EXT);
    gpu::GraphicsPipelineDesc desc;
    desc.name = "meshshader.crowd.impostor";
    desc.layout = &mLayout;
    desc.stages = {{VK_SHADER_STAGE_MESH_BIT_EXT, meshshader_crowd_impostor_mesh_spv},
                   {VK_SHADER_STAGE_FRAGMENT_BIT,
                    crowdImpostorFragment(device, crowd_impostor_frag_spv, crowd_impostor_frag_nearest_spv)}};
    // No face culled, as the other backends' cards (CrowdImpostorPass.cpp says why).
    desc.cullMode = VK_CULL_MODE_NONE;
    desc.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
    desc.colorFormats = {colorFormat};
    desc.depthFormat = depthFormat;
    mPipeline = gpu::Pipeline(device, desc);
}

void MeshshaderCrowdImpostorPass::record(gpu::FrameContext& frame, GpuCrowd& crowd,
                                         MeshshaderCrowdResources& resources, CrowdDescriptors& descriptors) {
    gpu::PassScope pass(frame, "crowd.impostor");
    VkCommandBuffer cmd = frame.cmd();
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mPipeline.handle());
    const uint32_t creatures = uint32_t(crowd.creatures().size());
    for (uint32_t c = 0; c < creatures; ++c) {
        const auto writes = descriptors.writes(c);
        mDevice->fn().cmdPushDescriptorSet(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mLayout.handle(), 0,
                                           uint32_t(writes.size()), writes.data());
        const uint32_t list = TS_LOD_IMPOSTOR * TS_CROWD_MAX_CHARACTERS + c;
        ImpostorPush push;
        push.countWord = list * TS_CROWD_ARG_DRAW_WORDS + 1;
        push.listBase = crowd.listBase(frame.slot(), TS_LOD_IMPOSTOR, c);
        vkCmdPushConstants(cmd, mLayout.handle(), VK_SHADER_STAGE_MESH_BIT_EXT, 0, sizeof push, &push);
        mDevice->fn().cmdDrawMeshTasksIndirect(cmd, resources.meshArgs().handle(),
                                               VkDeviceSize(list) * sizeof(shader::CrowdMeshCommand), 1,
                                               sizeof(shader::CrowdMeshCommand));
    }
}

} // namespace tessera::backends
