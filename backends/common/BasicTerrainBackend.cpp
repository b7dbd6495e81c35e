#include "BasicTerrainBackend.h"

#include "FrameUniformsBuilder.h"
#include "tessera/gpu/FrameContext.h"
#include "tessera/gpu/RenderTarget.h"

#include "terrain_basic.frag.spv.h"
#include "terrain_basic.vert.spv.h"

namespace tessera::backends {

void BasicTerrainBackend::checkRequirements(const backend::DeviceFeatures* device, backend::BackendCapabilities& caps) {
    if (!device) return;
    using backend::TessellationPath;
    if (caps.tessellation == TessellationPath::Hardware && !device->tessellationShader)
        caps.missing.push_back("tessellation shaders (tessellationShader)");
    if (caps.tessellation == TessellationPath::Hardware && device->tessellationShader &&
        float(device->maxTessellationLevel) < caps.maxTessFactor)
        caps.missing.push_back("tessellation level " + std::to_string(int(caps.maxTessFactor)) + " (device max " +
                               std::to_string(device->maxTessellationLevel) + ")");
    if (caps.usesGeometryShaders && !device->geometryShader) caps.missing.push_back("geometry shaders (geometryShader)");
    if (caps.usesTransformFeedback && !device->transformFeedback)
        caps.missing.push_back("transform feedback (VK_EXT_transform_feedback)");
}

Status BasicTerrainBackend::initialize(const backend::BackendInitInfo& info) {
    if (!info.device) return fail("this backend needs a Vulkan device");
    auto caps = capabilities(&info.features);
    if (!caps.supported()) {
        std::string missing;
        for (const auto& m : caps.missing) missing += (missing.empty() ? "" : ", ") + m;
        return fail("backend ", caps.name, " cannot run on ", info.features.deviceName, ": it lacks ", missing);
    }
    mDevice = info.device;
    const VkShaderStageFlags stages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
    mLayout = gpu::PipelineLayout(*mDevice,
                                  {{TS_BINDING_FRAME, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, stages},
                                   {TS_BINDING_TERRAIN, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, stages},
                                   {TS_BINDING_HEIGHTMAP, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, stages}},
                                  0, 0, caps.name + ".terrainBasic.layout");

    gpu::GraphicsPipelineDesc desc;
    desc.name = caps.name + ".terrainBasic.fill";
    desc.layout = &mLayout;
    desc.stages = {{VK_SHADER_STAGE_VERTEX_BIT, terrain_basic_vert_spv}, {VK_SHADER_STAGE_FRAGMENT_BIT, terrain_basic_frag_spv}};
    // Binding 0: the tile grid (per vertex); binding 1: visible tile index (per
    // instance), the D3D9-era way of instancing a patch over a terrain.
    desc.vertexBindings = {{0, sizeof(glm::vec2), VK_VERTEX_INPUT_RATE_VERTEX}, {1, sizeof(uint32_t), VK_VERTEX_INPUT_RATE_INSTANCE}};
    desc.vertexAttributes = {{0, 0, VK_FORMAT_R32G32_SFLOAT, 0}, {1, 1, VK_FORMAT_R32_UINT, 0}};
    desc.cullMode = VK_CULL_MODE_NONE;
    desc.colorFormats = {static_cast<VkFormat>(info.colorFormat)};
    desc.depthFormat = static_cast<VkFormat>(info.depthFormat);
    mFillPipeline = gpu::Pipeline(*mDevice, desc);
    if (info.features.fillModeNonSolid) {
        desc.name = caps.name + ".terrainBasic.wireframe";
        desc.polygonMode = VK_POLYGON_MODE_LINE;
        mWirePipeline = gpu::Pipeline(*mDevice, desc);
    }
    return {};
}

void BasicTerrainBackend::shutdown() {
    if (mDevice) mDevice->waitIdle();
    mTerrains.clear();
    mFillPipeline = {};
    mWirePipeline = {};
    mLayout = {};
    mDevice = nullptr;
}

Result<backend::TerrainHandle> BasicTerrainBackend::createTerrain(const backend::TerrainDesc& desc) {
    if (!desc.heightField) return fail("createTerrain: no height field");
    if (desc.tilesPerSide == 0 || desc.quadsPerTile == 0) return fail("createTerrain: empty tiling");
    mTerrains.push_back(std::make_unique<GpuTerrain>(*mDevice, desc));
    return backend::TerrainHandle{static_cast<uint32_t>(mTerrains.size() - 1)};
}

void BasicTerrainBackend::destroyTerrain(backend::TerrainHandle terrain) {
    if (!terrain.valid() || terrain.id >= mTerrains.size() || !mTerrains[terrain.id]) return;
    // The GPU may still read it in a frame in flight; release after that frame.
    auto* released = mTerrains[terrain.id].release();
    mDevice->deferDestroy([released] { delete released; });
}

void BasicTerrainBackend::beginFrame(const backend::FrameInfo& frame) {
    mFrameInfo = frame;
    mFrame = frame.gpu;
    mReport = {};
    mReport.frameIndex = frame.frameIndex;
    mFrameUniforms = mFrame->pushUniform(buildFrameUniforms(frame));
    mMainPassOpen = false;
}

void BasicTerrainBackend::ensureMainPass() {
    if (mMainPassOpen) return;
    const float clear[4] = {mFrameInfo.clearColor.r, mFrameInfo.clearColor.g, mFrameInfo.clearColor.b, 1.0f};
    mFrame->target().beginRendering(mFrame->cmd(), clear);
    mMainPassOpen = true;
}

void BasicTerrainBackend::drawTerrain(backend::TerrainHandle handle, const backend::TerrainDrawInfo& draw) {
    if (!handle.valid() || handle.id >= mTerrains.size() || !mTerrains[handle.id]) return;
    drawControlMesh(*mTerrains[handle.id], draw.visibleTiles, "terrain.lowres");
}

void BasicTerrainBackend::drawControlMesh(GpuTerrain& terrain, std::span<const uint32_t> tiles, const char* passName) {
    ensureMainPass();
    gpu::PassScope pass(*mFrame, passName);
    if (tiles.empty()) return;
    VkCommandBuffer cmd = mFrame->cmd();
    const bool wire = mFrameInfo.wireframe && mWirePipeline.valid();
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, (wire ? mWirePipeline : mFillPipeline).handle());

    VkDescriptorBufferInfo frameInfo = mFrameUniforms.descriptor();
    VkDescriptorBufferInfo terrainInfo{terrain.uniformBuffer().handle(), 0, VK_WHOLE_SIZE};
    VkDescriptorImageInfo heightInfo{terrain.sampler().handle(), terrain.heightMap().view(),
                                     VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    VkWriteDescriptorSet writes[3] = {};
    for (auto& w : writes) {
        w.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
        w.descriptorCount = 1;
    }
    writes[0].dstBinding = TS_BINDING_FRAME;
    writes[0].descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    writes[0].pBufferInfo = &frameInfo;
    writes[1].dstBinding = TS_BINDING_TERRAIN;
    writes[1].descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    writes[1].pBufferInfo = &terrainInfo;
    writes[2].dstBinding = TS_BINDING_HEIGHTMAP;
    writes[2].descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    writes[2].pImageInfo = &heightInfo;
    mDevice->fn().cmdPushDescriptorSet(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mLayout.handle(), 0, 3, writes);

    gpu::Buffer& tileStream = terrain.writeVisibleTiles(mFrame->slot(), tiles);
    VkBuffer vertexBuffers[2] = {terrain.gridVertices().handle(), tileStream.handle()};
    VkDeviceSize offsets[2] = {0, 0};
    vkCmdBindVertexBuffers(cmd, 0, 2, vertexBuffers, offsets);
    vkCmdBindIndexBuffer(cmd, terrain.gridIndices().handle(), 0, VK_INDEX_TYPE_UINT32);
    vkCmdDrawIndexed(cmd, terrain.gridIndexCount(), static_cast<uint32_t>(tiles.size()), 0, 0, 0);

    mReport.terrainTilesDrawn += static_cast<uint32_t>(tiles.size());
    mReport.trianglesSubmitted += uint64_t(terrain.gridIndexCount() / 3) * tiles.size();
    ++mReport.passes;
}

void BasicTerrainBackend::endFrame() {
    ensureMainPass(); // a frame with nothing drawn still clears the target
    mFrame->target().endRendering(mFrame->cmd());
    mMainPassOpen = false;
    mLastReport = mReport;
    mFrame = nullptr;
}

} // namespace tessera::backends
