#include "common/ShadowCasterPipeline.h"

#include "tessera/gpu/ShadowMapArray.h"

#include <algorithm>

namespace tessera::backends {

ShadowCasterPipeline::ShadowCasterPipeline(gpu::Device& device, gpu::GraphicsPipelineDesc desc,
                                           gpu::PipelineLayout layout, VkShaderStageFlags pushStages,
                                           const std::vector<gpu::ShaderStage>& casters, uint32_t pushOffset)
    : mLayout(std::move(layout)), mPushStages(pushStages), mPushOffset(pushOffset) {
    std::erase_if(desc.stages, [](const gpu::ShaderStage& s) { return s.stage == VK_SHADER_STAGE_FRAGMENT_BIT; });
    for (gpu::ShaderStage& s : desc.stages)
        for (const gpu::ShaderStage& caster : casters)
            if (s.stage == caster.stage) s.spirv = caster.spirv;
    desc.name += ".shadow";
    desc.layout = &mLayout;
    desc.polygonMode = VK_POLYGON_MODE_FILL;
    desc.cullMode = VK_CULL_MODE_NONE;
    desc.alphaBlend = false;
    desc.colorFormats.clear();
    desc.depthFormat = gpu::ShadowMapArray::kFormat;
    // A little bias on top of the receivers' normal offset and constant
    // bias (shadow_cascades.glsl): the slope term keeps surfaces grazing the
    // sun's rays, the characters' silhouettes, from shadowing themselves.
    desc.depthBiasConstant = 1.0f;
    desc.depthBiasSlope = 1.5f;
    mPipeline = gpu::Pipeline(device, desc);
}

void ShadowCasterPipeline::bind(VkCommandBuffer cmd, const shader::ShadowCasterPush& caster) const {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mPipeline.handle());
    vkCmdPushConstants(cmd, mLayout.handle(), mPushStages, mPushOffset, kPushBytes, &caster);
}

} // namespace tessera::backends
