#include "common/SkyPass.h"

#include "tessera/gpu/Device.h"
#include "tessera/shaders/FrameUniforms.h"

#include "sky.frag.spv.h"
#include "sky.vert.spv.h"

namespace tessera::backends {

SkyPass::SkyPass(gpu::Device& device, const std::string& backendName, VkFormat colorFormat, VkFormat depthFormat)
    : mDevice(&device) {
    const VkShaderStageFlags stages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
    mLayout = gpu::PipelineLayout(device, {{TS_BINDING_FRAME, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, stages}}, 0, 0,
                                  backendName + ".sky.layout");
    gpu::GraphicsPipelineDesc desc;
    desc.name = backendName + ".sky";
    desc.layout = &mLayout;
    desc.stages = {{VK_SHADER_STAGE_VERTEX_BIT, sky_vert_spv}, {VK_SHADER_STAGE_FRAGMENT_BIT, sky_frag_spv}};
    desc.cullMode = VK_CULL_MODE_NONE;
    // Depth 1 passes LESS_OR_EQUAL only where the clear value is left: the
    // sky shades the uncovered pixels and nothing else, and writes no depth.
    desc.depthTest = true;
    desc.depthWrite = false;
    desc.colorFormats = {colorFormat};
    desc.depthFormat = depthFormat;
    mPipeline = gpu::Pipeline(device, desc);
}

void SkyPass::record(gpu::FrameContext& frame, const gpu::UniformSlice& frameUniforms) {
    gpu::PassScope pass(frame, "sky");
    VkCommandBuffer cmd = frame.cmd();
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mPipeline.handle());
    VkDescriptorBufferInfo info = frameUniforms.descriptor();
    VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    write.dstBinding = TS_BINDING_FRAME;
    write.descriptorCount = 1;
    write.descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    write.pBufferInfo = &info;
    mDevice->fn().cmdPushDescriptorSet(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mLayout.handle(), 0, 1, &write);
    vkCmdDraw(cmd, 3, 1, 0, 0);
}

} // namespace tessera::backends
