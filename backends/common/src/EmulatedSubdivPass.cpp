#include "common/EmulatedSubdivPass.h"

#include "common/CommandHelpers.h"
#include "tessera/shaders/FrameUniforms.h"
#include "tessera/shaders/TessPattern.h"

#include "subdiv.frag.spv.h"
#include "subdiv_emulated.vert.spv.h"

#include <vector>

namespace tessera::backends {

EmulatedSubdivPass::EmulatedSubdivPass(gpu::Device& device, const std::string& backendName, VkFormat colorFormat,
                                       VkFormat depthFormat, bool wireframe)
    : mDevice(&device) {
    const VkShaderStageFlags stages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
    std::vector<gpu::BindingDesc> bindings = GpuSubdiv::evalBindings(stages);
    bindings.push_back({TS_BINDING_FRAME, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, stages});
    bindings.push_back({TS_BINDING_EMU_RECORDS, VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER, VK_SHADER_STAGE_VERTEX_BIT});
    mLayout = gpu::PipelineLayout(device, bindings, sizeof(uint32_t), VK_SHADER_STAGE_VERTEX_BIT,
                                  backendName + ".subdiv.layout");
    gpu::GraphicsPipelineDesc desc;
    desc.layout = &mLayout;
    desc.stages = {{VK_SHADER_STAGE_VERTEX_BIT, subdiv_emulated_vert_spv},
                   {VK_SHADER_STAGE_FRAGMENT_BIT, subdiv_frag_spv}};
    // One packed point reference per pattern vertex; the indirect commands'
    // firstVertex selects the piece, firstInstance the record and piece.
    desc.vertexBindings = {{0, sizeof(uint32_t), VK_VERTEX_INPUT_RATE_VERTEX}};
    desc.vertexAttributes = {{0, 0, VK_FORMAT_R32_UINT, 0}};
    // The pattern library lists triangles in the order the hardware emits
    // them for `ccw` (tessellator::PatternLibrary): hulldomain's winding.
    desc.colorFormats = {colorFormat};
    desc.depthFormat = depthFormat;
    mPipelines = SubdivPipelines(device, desc, backendName + ".subdiv", wireframe);
}

void EmulatedSubdivPass::record(gpu::FrameContext& frame, GpuSubdiv& surface, const EmulatedDrawSource& source,
                                const gpu::Buffer& patternVertices, const gpu::UniformSlice& frameUniforms,
                                const gpu::UniformSlice& uniforms, bool wireframe) {
    gpu::PassScope pass(frame, "subdiv.draw");
    if (source.records == VK_NULL_HANDLE || source.capacity == 0) return;
    VkCommandBuffer cmd = frame.cmd();
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mPipelines.get(surface, wireframe).handle());
    std::vector<VkWriteDescriptorSet> writes = surface.evalWrites(uniforms);
    const VkDescriptorBufferInfo frameInfo = frameUniforms.descriptor();
    writes.push_back(bufferWrite(TS_BINDING_FRAME, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, &frameInfo));
    writes.push_back(texelWrite(TS_BINDING_EMU_RECORDS, &source.records));
    mDevice->fn().cmdPushDescriptorSet(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mLayout.handle(), 0,
                                       uint32_t(writes.size()), writes.data());
    vkCmdPushConstants(cmd, mLayout.handle(), VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(uint32_t), &source.capacity);
    const VkBuffer patterns = patternVertices.handle();
    const VkDeviceSize offset = 0;
    vkCmdBindVertexBuffers(cmd, 0, 1, &patterns, &offset);
    // Five pattern pieces per domain, each an indirect command the
    // backend's own factor pass wrote on the GPU (culled domains: zeros).
    vkCmdDrawIndirect(cmd, source.commands, source.commandsOffset, source.capacity * TS_EMU_PIECES,
                      sizeof(VkDrawIndirectCommand));
}

} // namespace tessera::backends
