#include "MeshshaderTerrainPass.h"

#include "common/CommandHelpers.h"
#include "tessera/shaders/FrameUniforms.h"
#include "tessera/shaders/TerrainUniforms.h"
#include "tessera/shaders/TessFactors.h"
#include "tessera/shaders/TessMeshPattern.h"
#include "tessera/tessellator/MeshPatternLibrary.h"

#include "meshshader_terrain.mesh.spv.h"
#include "meshshader_terrain.task.spv.h"

#include "terrain_basic.frag.spv.h"

namespace tessera::backends {
namespace {

constexpr VkShaderStageFlags kStages =
    VK_SHADER_STAGE_TASK_BIT_EXT | VK_SHADER_STAGE_MESH_BIT_EXT | VK_SHADER_STAGE_FRAGMENT_BIT;
constexpr uint32_t kPatchesPerTask = TS_MESH_TASK_PATCHES;

} // namespace

MeshshaderTerrainPass::MeshshaderTerrainPass(gpu::Device& device, VkFormat colorFormat, VkFormat depthFormat,
                                             bool wireframe) {
    const tessellator::MeshPatternLibrary& library = tessellator::MeshPatternLibrary::quadFractionalOdd();
    mTables = MeshshaderPatternTables(device, library.keys(), library.triangles(), "meshshader.terrain");
    constexpr VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    mLayout = terrainLayout(device, kStages,
                            {{TS_BINDING_TESS, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, kStages},
                             {TS_BINDING_EDGE_LEVELS, storage, kStages},
                             {TS_BINDING_PATCH_LEVELS, storage, kStages},
                             {TS_BINDING_MESH_KEYS, storage, kStages},
                             {TS_BINDING_MESH_TRIANGLES, storage, kStages},
                             {TS_BINDING_MESH_PATCHES, storage, kStages}},
                            sizeof(uint32_t), VK_SHADER_STAGE_TASK_BIT_EXT, "meshshader.terrain.layout");
    gpu::GraphicsPipelineDesc desc;
    desc.layout = &mLayout;
    desc.stages = {{VK_SHADER_STAGE_TASK_BIT_EXT, meshshader_terrain_task_spv},
                   {VK_SHADER_STAGE_MESH_BIT_EXT, meshshader_terrain_mesh_spv},
                   {VK_SHADER_STAGE_FRAGMENT_BIT, terrain_basic_frag_spv}};
    desc.cullMode = VK_CULL_MODE_NONE;
    desc.colorFormats = {colorFormat};
    desc.depthFormat = depthFormat;
    mPipelines = FillWirePipelines(device, desc, "meshshader.terrain", wireframe);
}

void MeshshaderTerrainPass::record(gpu::FrameContext& frame, GpuTerrain& terrain,
                                   std::span<const uint32_t> visiblePatches, const gpu::UniformSlice& tessUniforms,
                                   const PushTerrainBindings& pushBindings, bool wireframe) {
    VkCommandBuffer cmd = frame.cmd();
    const uint32_t slot = frame.slot();
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mPipelines.get(wireframe).handle());
    const gpu::Buffer& patches = terrain.writeVisiblePatches(slot, visiblePatches);
    const VkDescriptorBufferInfo tess = tessUniforms.descriptor();
    const VkDescriptorBufferInfo edgeLevels{terrain.edgeLevels(slot).handle(), 0, VK_WHOLE_SIZE};
    const VkDescriptorBufferInfo patchLevels{terrain.patchLevels(slot).handle(), 0, VK_WHOLE_SIZE};
    const auto tables = mTables.descriptors();
    const VkDescriptorBufferInfo visible{patches.handle(), 0, VK_WHOLE_SIZE};
    constexpr VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    const VkWriteDescriptorSet writes[6] = {bufferWrite(TS_BINDING_TESS, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, &tess),
                                            bufferWrite(TS_BINDING_EDGE_LEVELS, storage, &edgeLevels),
                                            bufferWrite(TS_BINDING_PATCH_LEVELS, storage, &patchLevels),
                                            bufferWrite(TS_BINDING_MESH_KEYS, storage, &tables[0]),
                                            bufferWrite(TS_BINDING_MESH_TRIANGLES, storage, &tables[1]),
                                            bufferWrite(TS_BINDING_MESH_PATCHES, storage, &visible)};
    pushBindings(VK_PIPELINE_BIND_POINT_GRAPHICS, mLayout, writes);
    const auto count = static_cast<uint32_t>(visiblePatches.size());
    vkCmdPushConstants(cmd, mLayout.handle(), VK_SHADER_STAGE_TASK_BIT_EXT, 0, sizeof count, &count);
    frame.device().fn().cmdDrawMeshTasks(cmd, (count + kPatchesPerTask - 1) / kPatchesPerTask, 1, 1);
}

} // namespace tessera::backends
