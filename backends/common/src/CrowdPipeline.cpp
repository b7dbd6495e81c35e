#include "common/CrowdPipeline.h"

#include "tessera/gpu/Device.h"

namespace tessera::backends {

CrowdPipeline::CrowdPipeline(gpu::Device& device, CrowdDescriptors::Mode mode, std::span<const uint32_t> vertex,
                             std::span<const uint32_t> fragment, Stream stream, VkFrontFace frontFace,
                             VkCullModeFlags cullMode, VkFormat colorFormat, VkFormat depthFormat,
                             const std::string& name, std::span<const uint32_t> casterVertex)
    : mDevice(&device), mLayout(CrowdDescriptors::layout(device, mode,
                                                         VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT,
                                                         name + ".layout")) {
    gpu::GraphicsPipelineDesc desc;
    desc.name = name;
    desc.layout = &mLayout;
    desc.stages = {{VK_SHADER_STAGE_VERTEX_BIT, vertex}, {VK_SHADER_STAGE_FRAGMENT_BIT, fragment}};
    desc.vertexBindings = {{0, stream.stride, stream.rate}};
    desc.vertexAttributes = {{0, 0, stream.format, 0}};
    desc.cullMode = cullMode;
    desc.frontFace = frontFace;
    desc.colorFormats = {colorFormat};
    desc.depthFormat = depthFormat;
    mPipeline = gpu::Pipeline(device, desc);
    if (casterVertex.empty()) return;
    const VkShaderStageFlags vertexStage = VK_SHADER_STAGE_VERTEX_BIT;
    mShadow = ShadowCasterPipeline(device, desc,
                                   CrowdDescriptors::layout(device, mode, vertexStage, name + ".shadow.layout", {},
                                                            ShadowCasterPipeline::kPushBytes, vertexStage),
                                   vertexStage, {{VK_SHADER_STAGE_VERTEX_BIT, casterVertex}});
}

void CrowdPipeline::record(gpu::FrameContext& frame, const char* passName, GpuCrowd& crowd,
                           CrowdDescriptors& descriptors, VkBuffer stream, VkBuffer indices,
                           const std::function<void(VkCommandBuffer cmd, uint32_t creature)>& draw) const {
    VkCommandBuffer cmd = frame.cmd();
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mPipeline.handle());
    gpu::PassScope pass(frame, passName);
    recordCreatures(cmd, mLayout, crowd, descriptors, stream, indices, draw);
}

void CrowdPipeline::recordShadow(gpu::FrameContext& frame, GpuCrowd& crowd, CrowdDescriptors& descriptors,
                                 VkBuffer stream, VkBuffer indices, const shader::ShadowCasterPush& caster,
                                 const std::function<void(VkCommandBuffer cmd, uint32_t creature)>& draw) const {
    mShadow.bind(frame.cmd(), caster);
    recordCreatures(frame.cmd(), mShadow.layout(), crowd, descriptors, stream, indices, draw);
}

void CrowdPipeline::recordCreatures(VkCommandBuffer cmd, const gpu::PipelineLayout& layout, GpuCrowd& crowd,
                                    CrowdDescriptors& descriptors, VkBuffer stream, VkBuffer indices,
                                    const std::function<void(VkCommandBuffer cmd, uint32_t creature)>& draw) const {
    const VkDeviceSize zero = 0;
    vkCmdBindVertexBuffers(cmd, 0, 1, &stream, &zero);
    vkCmdBindIndexBuffer(cmd, indices, 0, VK_INDEX_TYPE_UINT32);
    for (uint32_t c = 0; c < crowd.creatures().size(); ++c) {
        const auto writes = descriptors.writes(c);
        mDevice->fn().cmdPushDescriptorSet(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout.handle(), 0,
                                           uint32_t(writes.size()), writes.data());
        draw(cmd, c);
    }
}

} // namespace tessera::backends
