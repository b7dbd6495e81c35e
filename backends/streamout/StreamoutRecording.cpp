#include "StreamoutRecording.h"

namespace tessera::backends::streamout {

void beginStreamOut(VkCommandBuffer cmd) {
    VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
    rendering.renderArea = {{0, 0}, {1, 1}};
    rendering.layerCount = 1;
    vkCmdBeginRendering(cmd, &rendering);
    // The pipelines' viewport and scissor are dynamic; they must be set even
    // though rasterizer discard never uses them.
    const VkViewport viewport{0.0f, 0.0f, 1.0f, 1.0f, 0.0f, 1.0f};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &rendering.renderArea);
}

void endStreamOut(VkCommandBuffer cmd) {
    vkCmdEndRendering(cmd);
}

gpu::GraphicsPipelineDesc streamOutPipelineDesc(std::string name, const gpu::PipelineLayout& layout,
                                                std::vector<gpu::ShaderStage> stages) {
    gpu::GraphicsPipelineDesc desc;
    desc.name = std::move(name);
    desc.layout = &layout;
    desc.stages = std::move(stages);
    desc.topology = VK_PRIMITIVE_TOPOLOGY_POINT_LIST;
    desc.cullMode = VK_CULL_MODE_NONE;
    desc.depthTest = false;
    desc.depthWrite = false;
    desc.rasterizerDiscard = true;
    return desc;
}

} // namespace tessera::backends::streamout
