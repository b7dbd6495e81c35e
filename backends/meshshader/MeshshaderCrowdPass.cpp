#include "MeshshaderCrowdPass.h"

#include "common/CommandHelpers.h"
#include "tessera/gpu/Barriers.h"
#include "tessera/gpu/Device.h"
#include "tessera/shaders/CrowdMeshlet.h"
#include "tessera/tessellator/MeshTrianglePatternLibrary.h"

#include "character.frag_crowd.spv.h"
#include "meshshader_character.mesh_crowd.spv.h"
#include "meshshader_character.mesh_crowd_shadow.spv.h"
#include "meshshader_character.task_crowd.spv.h"
#include "meshshader_crowd_args.comp.spv.h"
#include "meshshader_crowd_meshlet.mesh.spv.h"
#include "meshshader_crowd_meshlet.mesh_shadow.spv.h"
#include "meshshader_crowd_meshlet.task.spv.h"
#include "meshshader_crowd_meshlet.task_shadow.spv.h"

#include <vector>

namespace tessera::backends {
namespace {

constexpr VkShaderStageFlags kStages =
    VK_SHADER_STAGE_TASK_BIT_EXT | VK_SHADER_STAGE_MESH_BIT_EXT | VK_SHADER_STAGE_FRAGMENT_BIT;
constexpr VkDescriptorType kStorage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;

/// The task stages' push constants: the list (its count's word, its first
/// entry) and the mesh (the near tier: first cage index and triangles; the
/// others: first meshlet and meshlets).
struct TaskPush {
    uint32_t countWord = 0, listBase = 0, first = 0, count = 0;
};

// The casters' push constants: the task stage's, then the cascade's matrix
// for the mesh stage (TS_SHADOW_CASTER_OFFSET in CMakeLists.txt).
constexpr VkShaderStageFlags kShadowPushStages = VK_SHADER_STAGE_TASK_BIT_EXT | VK_SHADER_STAGE_MESH_BIT_EXT;
static_assert(sizeof(TaskPush) == 16, "the mesh stage's caster matrix follows the task stage's push constants");

uint32_t listOf(uint32_t tier, uint32_t creature) {
    return tier * TS_CROWD_MAX_CHARACTERS + creature;
}

} // namespace

MeshshaderCrowdPass::MeshshaderCrowdPass(gpu::Device& device, VkFormat colorFormat, VkFormat depthFormat)
    : mDevice(&device), mCull(device, "meshshader") {
    mArgsLayout = gpu::PipelineLayout(device,
                                      {{TS_BINDING_CROWD_ARGS, kStorage, VK_SHADER_STAGE_COMPUTE_BIT},
                                       {TS_BINDING_CROWD_MESH_ARGS, kStorage, VK_SHADER_STAGE_COMPUTE_BIT}},
                                      0, 0, "meshshader.crowd.meshTaskCommands.layout");
    mArgs = gpu::ComputePipeline(device, mArgsLayout, meshshader_crowd_args_comp_spv,
                                 "meshshader.crowd.meshTaskCommands");

    const tessellator::MeshTrianglePatternLibrary& library =
        tessellator::MeshTrianglePatternLibrary::uniformFractionalOdd();
    mTables = MeshshaderPatternTables(device, library.keys(), library.triangles(), "meshshader.crowd.near",
                                      library.crowdGroups());
    auto layout = [&](uint32_t pushBytes, VkShaderStageFlags pushStages, const std::string& name) {
        return CrowdDescriptors::layout(device, CrowdDescriptors::Mode::Storage, kStages, name,
                                        {{TS_BINDING_CROWD_INDICES, VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER, kStages},
                                         {TS_BINDING_MESH_KEYS, kStorage, kStages},
                                         {TS_BINDING_MESH_TRIANGLES, kStorage, kStages},
                                         {TS_BINDING_MESH_GROUPS, kStorage, kStages},
                                         {TS_BINDING_CROWD_MESHLETS, kStorage, kStages},
                                         {TS_BINDING_CROWD_MESHLET_VERTICES, kStorage, kStages},
                                         {TS_BINDING_CROWD_MESHLET_TRIANGLES, kStorage, kStages}},
                                        pushBytes, pushStages);
    };
    mLayout = layout(sizeof(TaskPush), VK_SHADER_STAGE_TASK_BIT_EXT, "meshshader.crowd.layout");
    const uint32_t shadowPushBytes = sizeof(TaskPush) + ShadowCasterPipeline::kPushBytes;

    gpu::GraphicsPipelineDesc desc;
    desc.layout = &mLayout;
    desc.colorFormats = {colorFormat};
    desc.depthFormat = depthFormat;
    desc.cullMode = VK_CULL_MODE_BACK_BIT;
    // The tessellated near tier winds as the tessellator's ccw ordering
    // makes it, which the Y-flipped projection turns clockwise (as
    // hulldomain's near tier and the character pass).
    desc.frontFace = VK_FRONT_FACE_CLOCKWISE;
    desc.name = "meshshader.crowd.near";
    desc.stages = {{VK_SHADER_STAGE_TASK_BIT_EXT, meshshader_character_task_crowd_spv},
                   {VK_SHADER_STAGE_MESH_BIT_EXT, meshshader_character_mesh_crowd_spv},
                   {VK_SHADER_STAGE_FRAGMENT_BIT, character_frag_crowd_spv}};
    mNear = gpu::Pipeline(device, desc);
    mNearShadow = ShadowCasterPipeline(
        device, desc, layout(shadowPushBytes, kShadowPushStages, "meshshader.crowd.near.shadow.layout"),
        kShadowPushStages, {{VK_SHADER_STAGE_MESH_BIT_EXT, meshshader_character_mesh_crowd_shadow_spv}},
        sizeof(TaskPush));
    // The meshlets keep the meshes' glTF counter-clockwise triangles
    // (meshoptimizer keeps each triangle's order), as crowd_mesh.vert draws them.
    desc.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
    desc.name = "meshshader.crowd.meshlets";
    desc.stages = {{VK_SHADER_STAGE_TASK_BIT_EXT, meshshader_crowd_meshlet_task_spv},
                   {VK_SHADER_STAGE_MESH_BIT_EXT, meshshader_crowd_meshlet_mesh_spv},
                   {VK_SHADER_STAGE_FRAGMENT_BIT, character_frag_crowd_spv}};
    mMeshlets = gpu::Pipeline(device, desc);
    // The casters' task stage keeps every meshlet (no camera culling).
    mMeshletsShadow = ShadowCasterPipeline(
        device, desc, layout(shadowPushBytes, kShadowPushStages, "meshshader.crowd.meshlets.shadow.layout"),
        kShadowPushStages,
        {{VK_SHADER_STAGE_TASK_BIT_EXT, meshshader_crowd_meshlet_task_shadow_spv},
         {VK_SHADER_STAGE_MESH_BIT_EXT, meshshader_crowd_meshlet_mesh_shadow_spv}},
        sizeof(TaskPush));
    mImpostor = MeshshaderCrowdImpostorPass(device, colorFormat, depthFormat);
}

void MeshshaderCrowdPass::recordCommands(VkCommandBuffer cmd, GpuCrowd& crowd, MeshshaderCrowdResources& resources) {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, mArgs.handle());
    const VkDescriptorBufferInfo args{crowd.args().handle(), 0, VK_WHOLE_SIZE};
    const VkDescriptorBufferInfo meshArgs{resources.meshArgs().handle(), 0, VK_WHOLE_SIZE};
    const VkWriteDescriptorSet writes[2] = {bufferWrite(TS_BINDING_CROWD_ARGS, kStorage, &args),
                                            bufferWrite(TS_BINDING_CROWD_MESH_ARGS, kStorage, &meshArgs)};
    mDevice->fn().cmdPushDescriptorSet(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, mArgsLayout.handle(), 0, 2, writes);
    vkCmdDispatch(cmd, 1, 1, 1);
    gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                       VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT, VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT);
}

void MeshshaderCrowdPass::recordCompute(gpu::FrameContext& frame, GpuCrowd& crowd,
                                        MeshshaderCrowdResources& resources, CrowdDescriptors& descriptors,
                                        uint32_t instanceCount) {
    mCull.record(frame, crowd, descriptors, instanceCount, VK_PIPELINE_STAGE_2_MESH_SHADER_BIT_EXT,
                 [&](VkCommandBuffer cmd) { recordCommands(cmd, crowd, resources); });
}

void MeshshaderCrowdPass::recordDraws(gpu::FrameContext& frame, GpuCrowd& crowd,
                                      MeshshaderCrowdResources& resources, CrowdDescriptors& descriptors) {
    static const char* const kPassNames[] = {"crowd.near", "crowd.middle", "crowd.far"};
    for (uint32_t tier = TS_LOD_NEAR; tier <= TS_LOD_FAR; ++tier) {
        gpu::PassScope pass(frame, kPassNames[tier]);
        vkCmdBindPipeline(frame.cmd(), VK_PIPELINE_BIND_POINT_GRAPHICS,
                          tier == TS_LOD_NEAR ? mNear.handle() : mMeshlets.handle());
        drawTier(frame.cmd(), mLayout, VK_SHADER_STAGE_TASK_BIT_EXT, tier, crowd, resources, descriptors, false);
    }
    mImpostor.record(frame, crowd, resources, descriptors);
}

void MeshshaderCrowdPass::recordShadow(gpu::FrameContext& frame, GpuCrowd& crowd,
                                       MeshshaderCrowdResources& resources, CrowdDescriptors& descriptors,
                                       const shader::ShadowCasterPush& caster) {
    // The middle and far tiers cast the far mesh's simplified casters'
    // meshlets (docs/LOOKS.md, "The casters"); the near tier its own; the
    // impostor tier none (CrowdImpostorPass.h).
    for (uint32_t tier = TS_LOD_NEAR; tier <= TS_LOD_FAR; ++tier) {
        const ShadowCasterPipeline& shadow = tier == TS_LOD_NEAR ? mNearShadow : mMeshletsShadow;
        shadow.bind(frame.cmd(), caster);
        drawTier(frame.cmd(), shadow.layout(), shadow.pushStages(), tier, crowd, resources, descriptors,
                 tier != TS_LOD_NEAR);
    }
}

void MeshshaderCrowdPass::drawTier(VkCommandBuffer cmd, const gpu::PipelineLayout& layout,
                                   VkShaderStageFlags pushStages, uint32_t tier, GpuCrowd& crowd,
                                   MeshshaderCrowdResources& resources, CrowdDescriptors& descriptors,
                                   bool casters) {
    const uint32_t creatures = uint32_t(crowd.creatures().size());
    const auto tables = mTables.descriptors();
    const VkDescriptorBufferInfo groups = mTables.groupsDescriptor();
    const VkBufferView indices = crowd.indicesView();
    const VkDescriptorBufferInfo meshlets{resources.meshletBuffer().handle(), 0, VK_WHOLE_SIZE};
    const VkDescriptorBufferInfo meshletVertices{resources.meshletVertices().handle(), 0, VK_WHOLE_SIZE};
    const VkDescriptorBufferInfo meshletTriangles{resources.meshletTriangles().handle(), 0, VK_WHOLE_SIZE};
    const VkWriteDescriptorSet extra[7] = {texelWrite(TS_BINDING_CROWD_INDICES, &indices),
                                           bufferWrite(TS_BINDING_MESH_GROUPS, kStorage, &groups),
                                           bufferWrite(TS_BINDING_MESH_KEYS, kStorage, &tables[0]),
                                           bufferWrite(TS_BINDING_MESH_TRIANGLES, kStorage, &tables[1]),
                                           bufferWrite(TS_BINDING_CROWD_MESHLETS, kStorage, &meshlets),
                                           bufferWrite(TS_BINDING_CROWD_MESHLET_VERTICES, kStorage, &meshletVertices),
                                           bufferWrite(TS_BINDING_CROWD_MESHLET_TRIANGLES, kStorage, &meshletTriangles)};
    std::vector<VkWriteDescriptorSet> writes;
    for (uint32_t c = 0; c < creatures; ++c) {
        const auto shared = descriptors.writes(c);
        writes.assign(shared.begin(), shared.end());
        writes.insert(writes.end(), std::begin(extra), std::end(extra));
        mDevice->fn().cmdPushDescriptorSet(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout.handle(), 0,
                                           uint32_t(writes.size()), writes.data());
        const uint32_t list = listOf(tier, c);
        TaskPush push;
        push.countWord = list * TS_CROWD_ARG_DRAW_WORDS + 1;
        push.listBase = crowd.listBase(crowd.lastSlot(), tier, c); // this frame's instances
        if (tier == TS_LOD_NEAR) {
            push.first = crowd.creatures()[c].cageFirstIndex;
            push.count = crowd.creatures()[c].cageTriangles;
        } else {
            const MeshshaderCrowdResources::MeshletRange range =
                casters ? resources.casterMeshlets(tier, c) : resources.meshlets(tier, c);
            push.first = range.first;
            push.count = range.count;
        }
        vkCmdPushConstants(cmd, layout.handle(), pushStages, 0, sizeof push, &push);
        const uint32_t command = casters ? shader::tsCrowdCasterCommand(tier, c) : list;
        mDevice->fn().cmdDrawMeshTasksIndirect(cmd, resources.meshArgs().handle(),
                                               VkDeviceSize(command) * sizeof(shader::CrowdMeshCommand), 1,
                                               sizeof(shader::CrowdMeshCommand));
    }
}

} // namespace tessera::backends
