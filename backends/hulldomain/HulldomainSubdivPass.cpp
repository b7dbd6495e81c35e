#include "HulldomainSubdivPass.h"

#include "common/CommandHelpers.h"
#include "tessera/shaders/FrameUniforms.h"

#include <algorithm>

#include "hulldomain_subdiv_patch.tesc.spv.h"
#include "hulldomain_subdiv_patch.tese.spv.h"
#include "hulldomain_subdiv_patch.vert.spv.h"
#include "subdiv.frag.spv.h"

namespace tessera::backends {

namespace {
constexpr uint32_t kMaxTessellatedVertices = 65536;
constexpr uint32_t kVerticesPerDomainAt64 = 65 * 65; // a quad domain at level 64
}

HulldomainSubdivPass::HulldomainSubdivPass(gpu::Device& device, VkFormat colorFormat, VkFormat depthFormat,
                                           bool wireframe)
    : mDevice(&device) {
    const VkShaderStageFlags graphics = VK_SHADER_STAGE_ALL_GRAPHICS;
    std::vector<gpu::BindingDesc> bindings = GpuSubdiv::levelBindings(graphics);
    bindings.push_back({TS_BINDING_FRAME, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, graphics});
    mLayout = gpu::PipelineLayout(device, bindings, 0, 0, "hulldomain.subdiv.layout");
    gpu::GraphicsPipelineDesc desc;
    desc.layout = &mLayout;
    desc.stages = {{VK_SHADER_STAGE_VERTEX_BIT, hulldomain_subdiv_patch_vert_spv},
                   {VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT, hulldomain_subdiv_patch_tesc_spv},
                   {VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT, hulldomain_subdiv_patch_tese_spv},
                   {VK_SHADER_STAGE_FRAGMENT_BIT, subdiv_frag_spv}};
    desc.topology = VK_PRIMITIVE_TOPOLOGY_PATCH_LIST;
    desc.patchControlPoints = 1;
    desc.colorFormats = {colorFormat};
    desc.depthFormat = depthFormat;
    mPipelines = SubdivPipelines(device, desc, "hulldomain.subdiv", wireframe);
}

void HulldomainSubdivPass::recordDraw(gpu::FrameContext& frame, GpuSubdiv& surface,
                                      const gpu::UniformSlice& frameUniforms, const gpu::UniformSlice& uniforms,
                                      bool wireframe) {
    VkCommandBuffer cmd = frame.cmd();
    gpu::PassScope pass(frame, "subdiv.draw");
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mPipelines.get(surface, wireframe).handle());
    std::vector<VkWriteDescriptorSet> writes = surface.levelWrites(uniforms);
    const VkDescriptorBufferInfo frameInfo = frameUniforms.descriptor();
    writes.push_back(bufferWrite(TS_BINDING_FRAME, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, &frameInfo));
    mDevice->fn().cmdPushDescriptorSet(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mLayout.handle(), 0,
                                       uint32_t(writes.size()), writes.data());
    // At most 65,536 tessellated vertices per draw: lavapipe indexes a
    // draw's tessellated vertices with 16 bits and joins far-apart domains'
    // points beyond that (stray triangles across the surface from level 32 on
    // a mesh of 60 domains). The batches cost a GPU nothing measurable.
    const uint32_t perDraw = kMaxTessellatedVertices / kVerticesPerDomainAt64;
    for (uint32_t first = 0; first < surface.domainCount(); first += perDraw)
        vkCmdDraw(cmd, std::min(perDraw, surface.domainCount() - first), 1, first, 0);
}

} // namespace tessera::backends
