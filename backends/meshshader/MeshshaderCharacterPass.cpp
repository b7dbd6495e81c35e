#include "MeshshaderCharacterPass.h"

#include "common/CommandHelpers.h"
#include "tessera/gpu/FrameContext.h"
#include "tessera/shaders/FrameUniforms.h"
#include "tessera/tessellator/MeshTrianglePatternLibrary.h"

#include "character.frag.spv.h"
#include "meshshader_character.mesh.spv.h"
#include "meshshader_character.mesh_shadow.spv.h"
#include "meshshader_character.mesh_single.spv.h"
#include "meshshader_character.mesh_single_shadow.spv.h"
#include "meshshader_character.task.spv.h"

namespace tessera::backends {
namespace {

constexpr VkShaderStageFlags kStages =
    VK_SHADER_STAGE_TASK_BIT_EXT | VK_SHADER_STAGE_MESH_BIT_EXT | VK_SHADER_STAGE_FRAGMENT_BIT;
// Cage triangles per task workgroup (meshshader_character.glsl).
constexpr uint32_t kTrianglesPerTask = 32;
// The casters' push constants: the task stage's, then the cascade's matrix
// for the mesh stage (TS_SHADOW_CASTER_OFFSET in CMakeLists.txt).
constexpr uint32_t kShadowPushOffset = 16;
constexpr VkShaderStageFlags kShadowPushStages = VK_SHADER_STAGE_TASK_BIT_EXT | VK_SHADER_STAGE_MESH_BIT_EXT;

} // namespace

MeshshaderCharacterPass::MeshshaderCharacterPass(gpu::Device& device, VkFormat colorFormat, VkFormat depthFormat,
                                                 bool wireframe) {
    const tessellator::MeshTrianglePatternLibrary& library = tessellator::MeshTrianglePatternLibrary::uniformFractionalOdd();
    mTables = MeshshaderPatternTables(device, library.keys(), library.triangles(), "meshshader.character",
                                      library.groups());
    constexpr VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    auto layout = [&](uint32_t pushBytes, VkShaderStageFlags pushStages, const std::string& name) {
        return characterLayout(device, CharacterBindings::Draw, kStages, storage, pushBytes, pushStages, name,
                               {{TS_BINDING_MESH_KEYS, storage, kStages},
                                {TS_BINDING_MESH_TRIANGLES, storage, kStages},
                                {TS_BINDING_MESH_GROUPS, storage, kStages},
                                {TS_BINDING_MESH_PATCHES, storage, kStages}});
    };
    mLayout = layout(sizeof(uint32_t), VK_SHADER_STAGE_TASK_BIT_EXT, "meshshader.characterPatches.layout");
    for (int single = 0; single < 2; ++single) {
        gpu::GraphicsPipelineDesc desc;
        desc.layout = &mLayout;
        using Spirv = std::span<const uint32_t>;
        desc.stages = {{VK_SHADER_STAGE_TASK_BIT_EXT, meshshader_character_task_spv},
                       {VK_SHADER_STAGE_MESH_BIT_EXT, single ? Spirv(meshshader_character_mesh_single_spv)
                                                             : Spirv(meshshader_character_mesh_spv)},
                       {VK_SHADER_STAGE_FRAGMENT_BIT, character_frag_spv}};
        // As hulldomain: Camera::projection flips Y, which turns glTF's
        // counter-clockwise front faces into clockwise ones on screen.
        desc.cullMode = VK_CULL_MODE_BACK_BIT;
        desc.frontFace = VK_FRONT_FACE_CLOCKWISE;
        desc.colorFormats = {colorFormat};
        desc.depthFormat = depthFormat;
        desc.name = std::string("meshshader.character.") + (single ? "singlePass" : "twoPass");
        mPipelines[single] = FillWirePipelines(device, desc, desc.name, wireframe);
        mShadow[single] = ShadowCasterPipeline(
            device, desc, layout(kShadowPushOffset + ShadowCasterPipeline::kPushBytes, kShadowPushStages,
                                 desc.name + ".shadow.layout"),
            kShadowPushStages,
            {{VK_SHADER_STAGE_MESH_BIT_EXT, single ? Spirv(meshshader_character_mesh_single_shadow_spv)
                                                   : Spirv(meshshader_character_mesh_shadow_spv)}},
            kShadowPushOffset);
    }
}

void MeshshaderCharacterPass::record(gpu::FrameContext& frame, const CharacterInstance& instance,
                                     backend::CharacterPath path, bool wireframe, const CharacterPushFn& push) {
    const int single = path == backend::CharacterPath::SinglePass ? 1 : 0;
    vkCmdBindPipeline(frame.cmd(), VK_PIPELINE_BIND_POINT_GRAPHICS, mPipelines[single].get(wireframe).handle());
    drawTasks(frame, mLayout, VK_SHADER_STAGE_TASK_BIT_EXT, instance, push);
}

void MeshshaderCharacterPass::recordShadow(gpu::FrameContext& frame, const CharacterInstance& instance,
                                           backend::CharacterPath path, const shader::ShadowCasterPush& caster,
                                           const CharacterPushFn& push) {
    const ShadowCasterPipeline& shadow = mShadow[path == backend::CharacterPath::SinglePass ? 1 : 0];
    shadow.bind(frame.cmd(), caster);
    drawTasks(frame, shadow.layout(), shadow.pushStages(), instance, push);
}

void MeshshaderCharacterPass::drawTasks(gpu::FrameContext& frame, const gpu::PipelineLayout& layout,
                                        VkShaderStageFlags pushStages, const CharacterInstance& instance,
                                        const CharacterPushFn& push) {
    VkCommandBuffer cmd = frame.cmd();
    GpuCharacter& c = *instance.character;
    const VkDescriptorBufferInfo cage{c.vertices().handle(), 0, VK_WHOLE_SIZE};
    VkDescriptorBufferInfo compressed{c.vertices().handle(), 0, VK_WHOLE_SIZE};
    if (instance.compressed) compressed = {instance.compressed->buffer.handle(), 0, VK_WHOLE_SIZE};
    const VkDescriptorBufferInfo indices{c.indices().handle(), 0, VK_WHOLE_SIZE};
    const auto tables = mTables.descriptors();
    const VkDescriptorBufferInfo groups = mTables.groupsDescriptor();
    constexpr VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    const VkWriteDescriptorSet writes[6] = {bufferWrite(TS_BINDING_MESH_GROUPS, storage, &groups),
                                            bufferWrite(TS_BINDING_CAGE_VERTICES, storage, &cage),
                                            bufferWrite(TS_BINDING_COMPRESSED, storage, &compressed),
                                            bufferWrite(TS_BINDING_MESH_KEYS, storage, &tables[0]),
                                            bufferWrite(TS_BINDING_MESH_TRIANGLES, storage, &tables[1]),
                                            bufferWrite(TS_BINDING_MESH_PATCHES, storage, &indices)};
    push(VK_PIPELINE_BIND_POINT_GRAPHICS, CharacterBindings::Draw, layout, instance, writes);
    const uint32_t triangles = c.triangleCount();
    vkCmdPushConstants(cmd, layout.handle(), pushStages, 0, sizeof triangles, &triangles);
    frame.device().fn().cmdDrawMeshTasks(cmd, (triangles + kTrianglesPerTask - 1) / kTrianglesPerTask, 1, 1);
}

} // namespace tessera::backends
