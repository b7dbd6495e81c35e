#include "common/ComputeTessFactorPass.h"

#include "common/TerrainBindings.h"
#include "tessera/gpu/Barriers.h"

#include "common/CommandHelpers.h"

#include "tessera/shaders/FrameUniforms.h"
#include "tessera/shaders/TerrainUniforms.h"

#include "terrain_factors.comp.spv.h"

namespace tessera::backends {

ComputeTessFactorPass::ComputeTessFactorPass(gpu::Device& device, const std::string& backendName) {
    const VkShaderStageFlags compute = VK_SHADER_STAGE_COMPUTE_BIT;
    mLayout = terrainLayout(device, compute,
                            {{TS_BINDING_TESS, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, compute},
                             {TS_BINDING_EDGE_ERROR, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, compute},
                             {TS_BINDING_PATCH_ERROR, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, compute},
                             {TS_BINDING_EDGE_LEVELS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, compute},
                             {TS_BINDING_PATCH_LEVELS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, compute}},
                            0, 0, backendName + ".terrainFactors.layout");
    mPipeline =
        gpu::ComputePipeline(device, mLayout, terrain_factors_comp_spv, backendName + ".terrainFactors");
}

void ComputeTessFactorPass::record(gpu::FrameContext& frame, GpuTerrain& terrain,
                                   const gpu::UniformSlice& tessUniforms, const PushTerrainBindings& pushBindings,
                                   VkPipelineStageFlags2 reader) {
    gpu::PassScope pass(frame, "terrain.factors");
    VkCommandBuffer cmd = frame.cmd();
    const uint32_t slot = frame.slot();
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, mPipeline.handle());
    const VkDescriptorBufferInfo tess = tessUniforms.descriptor();
    const VkDescriptorBufferInfo edgeErrors{terrain.edgeErrors(slot).handle(), 0, VK_WHOLE_SIZE};
    const VkDescriptorBufferInfo patchErrors{terrain.patchErrors(slot).handle(), 0, VK_WHOLE_SIZE};
    const VkDescriptorBufferInfo edgeLevels{terrain.edgeLevels(slot).handle(), 0, VK_WHOLE_SIZE};
    const VkDescriptorBufferInfo patchLevels{terrain.patchLevels(slot).handle(), 0, VK_WHOLE_SIZE};
    constexpr VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    VkWriteDescriptorSet writes[5] = {bufferWrite(TS_BINDING_TESS, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, &tess),
                                      bufferWrite(TS_BINDING_EDGE_ERROR, storage, &edgeErrors),
                                      bufferWrite(TS_BINDING_PATCH_ERROR, storage, &patchErrors),
                                      bufferWrite(TS_BINDING_EDGE_LEVELS, storage, &edgeLevels),
                                      bufferWrite(TS_BINDING_PATCH_LEVELS, storage, &patchLevels)};
    pushBindings(VK_PIPELINE_BIND_POINT_COMPUTE, mLayout, writes);
    const uint32_t invocations = terrain.edgeCount() + terrain.patchCount();
    vkCmdDispatch(cmd, (invocations + 63) / 64, 1, 1);

    gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                       reader, VK_ACCESS_2_SHADER_STORAGE_READ_BIT);
}

} // namespace tessera::backends
