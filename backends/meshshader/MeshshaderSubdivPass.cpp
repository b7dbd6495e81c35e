#include "MeshshaderSubdivPass.h"

#include "common/CommandHelpers.h"
#include "tessera/shaders/FrameUniforms.h"
#include "tessera/tessellator/MeshPatternLibrary.h"

#include "meshshader_subdiv.mesh.spv.h"
#include "meshshader_subdiv.task.spv.h"
#include "subdiv.frag.spv.h"

namespace tessera::backends {
namespace {

constexpr VkShaderStageFlags kStages =
    VK_SHADER_STAGE_TASK_BIT_EXT | VK_SHADER_STAGE_MESH_BIT_EXT | VK_SHADER_STAGE_FRAGMENT_BIT;
constexpr uint32_t kDomainsPerTask = TS_MESH_TASK_PATCHES;

} // namespace

MeshshaderSubdivPass::MeshshaderSubdivPass(gpu::Device& device, VkFormat colorFormat, VkFormat depthFormat,
                                           bool wireframe)
    : mDevice(&device) {
    const tessellator::MeshPatternLibrary& library = tessellator::MeshPatternLibrary::quadFractionalOdd();
    mTables = MeshshaderPatternTables(device, library.keys(), library.triangles(), "meshshader.subdiv");
    std::vector<gpu::BindingDesc> bindings = GpuSubdiv::levelBindings(kStages);
    bindings.push_back({TS_BINDING_FRAME, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, kStages});
    bindings.push_back({TS_BINDING_MESH_KEYS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kStages});
    bindings.push_back({TS_BINDING_MESH_TRIANGLES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kStages});
    mLayout = gpu::PipelineLayout(device, bindings, sizeof(uint32_t), VK_SHADER_STAGE_TASK_BIT_EXT,
                                  "meshshader.subdiv.layout");
    gpu::GraphicsPipelineDesc desc;
    desc.layout = &mLayout;
    desc.stages = {{VK_SHADER_STAGE_TASK_BIT_EXT, meshshader_subdiv_task_spv},
                   {VK_SHADER_STAGE_MESH_BIT_EXT, meshshader_subdiv_mesh_spv},
                   {VK_SHADER_STAGE_FRAGMENT_BIT, subdiv_frag_spv}};
    desc.colorFormats = {colorFormat};
    desc.depthFormat = depthFormat;
    mPipelines = SubdivPipelines(device, desc, "meshshader.subdiv", wireframe);
}

void MeshshaderSubdivPass::recordDraw(gpu::FrameContext& frame, GpuSubdiv& surface,
                                      const gpu::UniformSlice& frameUniforms, const gpu::UniformSlice& uniforms,
                                      bool wireframe) {
    VkCommandBuffer cmd = frame.cmd();
    gpu::PassScope pass(frame, "subdiv.draw");
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mPipelines.get(surface, wireframe).handle());
    std::vector<VkWriteDescriptorSet> writes = surface.levelWrites(uniforms);
    const VkDescriptorBufferInfo frameInfo = frameUniforms.descriptor();
    const auto tables = mTables.descriptors();
    writes.push_back(bufferWrite(TS_BINDING_FRAME, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, &frameInfo));
    writes.push_back(bufferWrite(TS_BINDING_MESH_KEYS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, &tables[0]));
    writes.push_back(bufferWrite(TS_BINDING_MESH_TRIANGLES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, &tables[1]));
    mDevice->fn().cmdPushDescriptorSet(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mLayout.handle(), 0,
                                       uint32_t(writes.size()), writes.data());
    const uint32_t domains = surface.domainCount();
    vkCmdPushConstants(cmd, mLayout.handle(), VK_SHADER_STAGE_TASK_BIT_EXT, 0, sizeof domains, &domains);
    mDevice->fn().cmdDrawMeshTasks(cmd, (domains + kDomainsPerTask - 1) / kDomainsPerTask, 1, 1);
}

} // namespace tessera::backends
