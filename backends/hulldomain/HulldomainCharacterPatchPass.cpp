#include "HulldomainCharacterPatchPass.h"

#include "common/CommandHelpers.h"
#include "tessera/shaders/FrameUniforms.h"
#include "tessera/gpu/FrameContext.h"

#include "character.frag.spv.h"
#include "hulldomain_character_patch.tesc.spv.h"
#include "hulldomain_character_patch.tesc_single.spv.h"
#include "hulldomain_character_patch.tese.spv.h"
#include "hulldomain_character_patch.tese_shadow.spv.h"
#include "hulldomain_character_patch.tese_single.spv.h"
#include "hulldomain_character_patch.tese_single_shadow.spv.h"
#include "hulldomain_character_patch.vert.spv.h"
#include "hulldomain_character_patch.vert_single.spv.h"

namespace tessera::backends {

HulldomainCharacterPatchPass::HulldomainCharacterPatchPass(gpu::Device& device, VkFormat colorFormat,
                                                           VkFormat depthFormat, bool wireframe) {
    const VkShaderStageFlags graphics = VK_SHADER_STAGE_ALL_GRAPHICS;
    mLayout = characterLayout(device, CharacterBindings::Draw, graphics, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 0, 0,
                              "hulldomain.characterPatches.layout");
    for (int single = 0; single < 2; ++single) {
        gpu::GraphicsPipelineDesc desc;
        desc.layout = &mLayout;
        using Spirv = std::span<const uint32_t>;
        desc.stages = {
            {VK_SHADER_STAGE_VERTEX_BIT,
             single ? Spirv(hulldomain_character_patch_vert_single_spv) : Spirv(hulldomain_character_patch_vert_spv)},
            {VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT,
             single ? Spirv(hulldomain_character_patch_tesc_single_spv) : Spirv(hulldomain_character_patch_tesc_spv)},
            {VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT,
             single ? Spirv(hulldomain_character_patch_tese_single_spv) : Spirv(hulldomain_character_patch_tese_spv)},
            {VK_SHADER_STAGE_FRAGMENT_BIT, character_frag_spv}};
        // No vertex streams: the vertex stage reads by gl_VertexIndex.
        desc.topology = VK_PRIMITIVE_TOPOLOGY_PATCH_LIST;
        desc.patchControlPoints = 3;
        // Back faces culled. Camera::projection flips Y for Vulkan's
        // framebuffer, which turns glTF's counter-clockwise front faces into
        // clockwise ones on screen.
        desc.cullMode = VK_CULL_MODE_BACK_BIT;
        desc.frontFace = VK_FRONT_FACE_CLOCKWISE;
        desc.colorFormats = {colorFormat};
        desc.depthFormat = depthFormat;
        desc.name = std::string("hulldomain.character.") + (single ? "singlePass" : "twoPass");
        mPipelines[single] = FillWirePipelines(device, desc, desc.name, wireframe);
        mShadow[single] = ShadowCasterPipeline(
            device, desc,
            characterLayout(device, CharacterBindings::Draw, graphics, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                            ShadowCasterPipeline::kPushBytes, graphics, desc.name + ".shadow.layout"),
            graphics,
            {{VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT, single ? Spirv(hulldomain_character_patch_tese_single_shadow_spv)
                                                                  : Spirv(hulldomain_character_patch_tese_shadow_spv)}});
    }
}

void HulldomainCharacterPatchPass::record(gpu::FrameContext& frame, const CharacterInstance& instance,
                                          backend::CharacterPath path, bool wireframe, const CharacterPushFn& push) {
    const int single = path == backend::CharacterPath::SinglePass ? 1 : 0;
    vkCmdBindPipeline(frame.cmd(), VK_PIPELINE_BIND_POINT_GRAPHICS, mPipelines[single].get(wireframe).handle());
    drawPatches(frame.cmd(), mLayout, instance, push);
}

void HulldomainCharacterPatchPass::recordShadow(gpu::FrameContext& frame, const CharacterInstance& instance,
                                                backend::CharacterPath path, const shader::ShadowCasterPush& caster,
                                                const CharacterPushFn& push) {
    const ShadowCasterPipeline& shadow = mShadow[path == backend::CharacterPath::SinglePass ? 1 : 0];
    shadow.bind(frame.cmd(), caster);
    drawPatches(frame.cmd(), shadow.layout(), instance, push);
}

void HulldomainCharacterPatchPass::drawPatches(VkCommandBuffer cmd, const gpu::PipelineLayout& layout,
                                               const CharacterInstance& instance, const CharacterPushFn& push) {
    GpuCharacter& c = *instance.character;
    const VkDescriptorBufferInfo cage{c.vertices().handle(), 0, VK_WHOLE_SIZE};
    VkDescriptorBufferInfo compressed{c.vertices().handle(), 0, VK_WHOLE_SIZE};
    if (instance.compressed) compressed = {instance.compressed->buffer.handle(), 0, VK_WHOLE_SIZE};
    const VkWriteDescriptorSet writes[2] = {
        bufferWrite(TS_BINDING_CAGE_VERTICES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, &cage),
        bufferWrite(TS_BINDING_COMPRESSED, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, &compressed)};
    push(VK_PIPELINE_BIND_POINT_GRAPHICS, CharacterBindings::Draw, layout, instance, writes);
    vkCmdBindIndexBuffer(cmd, c.indices().handle(), 0, VK_INDEX_TYPE_UINT32);
    vkCmdDrawIndexed(cmd, c.triangleCount() * 3, 1, 0, 0, 0);
}

} // namespace tessera::backends
