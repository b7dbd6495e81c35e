#include "common/EmulatedTerrainBackend.h"

#include "tessera/shaders/FrameUniforms.h"
#include "tessera/shaders/TerrainUniforms.h"
#include "tessera/shaders/TessPattern.h"
#include "tessera/backend/SubdivMeshData.h"
#include "tessera/terrain/Terrain.h"
#include "tessera/tessellator/PatternLibrary.h"

#include "terrain_basic.frag.spv.h"
#include "terrain_emulated.vert.spv.h"

#include <string>

namespace tessera::backends {

Status EmulatedTerrainBackend::initializeTechnique(const backend::BackendInitInfo& info) {
    const std::string name = capabilities(nullptr).name;
    // The pattern library is the emulated unit's fixed function: built once
    // from the CPU tessellator's stitching rules and never touched again.
    const tessellator::PatternLibrary& library = tessellator::PatternLibrary::quadFractionalOdd();
    mPatternVertices = gpu::Buffer(*mDevice, library.vertices().size_bytes(), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT,
                                   gpu::MemoryUsage::GpuOnly, name + ".tessellator.patterns");
    mPatternVertices.upload(library.vertices());
    shader::TsEmuKeyTable keys{};
    for (size_t k = 0; k < library.pieces().size(); ++k)
        keys.pieces[k] = glm::uvec4(library.pieces()[k].firstVertex, library.pieces()[k].vertexCount, 0u, 0u);
    mKeyTable = gpu::Buffer(*mDevice, sizeof keys, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, gpu::MemoryUsage::GpuOnly,
                            name + ".tessellator.keys");
    mKeyTable.upload(std::span<const shader::TsEmuKeyTable>(&keys, 1));

    const VkShaderStageFlags stages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
    mLayout = gpu::PipelineLayout(*mDevice,
                                  {{TS_BINDING_FRAME, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, stages},
                                   {TS_BINDING_TERRAIN, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, stages},
                                   {TS_BINDING_HEIGHTMAP, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, stages},
                                   {TS_BINDING_SUN_VISIBILITY, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, stages},
                                   {TS_BINDING_DETAIL, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, stages},
                                   {TS_BINDING_CHARACTER_SHADOW, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, stages},
                                   {TS_BINDING_EMU_RECORDS, VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER,
                                    VK_SHADER_STAGE_VERTEX_BIT}},
                                  sizeof(uint32_t), VK_SHADER_STAGE_VERTEX_BIT, name + ".terrainEmulated.layout");
    gpu::GraphicsPipelineDesc desc;
    desc.name = name + ".terrainEmulated.fill";
    desc.layout = &mLayout;
    desc.stages = {{VK_SHADER_STAGE_VERTEX_BIT, terrain_emulated_vert_spv},
                   {VK_SHADER_STAGE_FRAGMENT_BIT, terrain_basic_frag_spv}};
    // One packed point reference per pattern vertex; the indirect commands'
    // firstVertex selects the piece.
    desc.vertexBindings = {{0, sizeof(uint32_t), VK_VERTEX_INPUT_RATE_VERTEX}};
    desc.vertexAttributes = {{0, 0, VK_FORMAT_R32_UINT, 0}};
    desc.cullMode = VK_CULL_MODE_NONE;
    desc.colorFormats = {static_cast<VkFormat>(info.colorFormat)};
    desc.depthFormat = static_cast<VkFormat>(info.depthFormat);
    mFillPipeline = gpu::Pipeline(*mDevice, desc);
    if (mWireframeSupported) {
        desc.name = name + ".terrainEmulated.wireframe";
        desc.polygonMode = VK_POLYGON_MODE_LINE;
        mWirePipeline = gpu::Pipeline(*mDevice, desc);
    }
    mCharacterPass = EmulatedCharacterPass(*mDevice, name, static_cast<VkFormat>(info.colorFormat),
                                           static_cast<VkFormat>(info.depthFormat), mWireframeSupported);
    if (Status factors = initializeFactorPasses(info); !factors) return factors;
    if (capabilities(nullptr).subdiv) {
        mSubdivPass = EmulatedSubdivPass(*mDevice, name, static_cast<VkFormat>(info.colorFormat),
                                         static_cast<VkFormat>(info.depthFormat), mWireframeSupported);
        // The backend's subdivWriteUsage is known now.
        initializeSubdiv();
    }
    return {};
}

void EmulatedTerrainBackend::shutdownTechnique() {
    shutdownFactorPasses();
    mSubdivPass = {};
    mSubdivSource = {};
    mCharacterPass = {};
    mFillPipeline = {};
    mWirePipeline = {};
    mLayout = {};
    mKeyTable = {};
    mPatternVertices = {};
}

Result<backend::TerrainHandle> EmulatedTerrainBackend::createTerrain(const backend::TerrainDesc& desc) {
    if (desc.terrain) {
        const uint64_t texels = 2ull * desc.terrain->grid().patchCount();
        const uint32_t limit = mDevice->properties().limits.maxTexelBufferElements;
        if (texels > limit)
            return fail("backend ", capabilities(nullptr).name, ": a terrain of ",
                        std::to_string(desc.terrain->grid().patchCount()), " patches needs ", std::to_string(texels),
                        " record texels, more than this device's maxTexelBufferElements (", std::to_string(limit), ")");
    }
    return BasicTerrainBackend::createTerrain(desc);
}

Result<backend::SubdivHandle> EmulatedTerrainBackend::createSubdiv(const backend::SubdivDesc& desc) {
    if (desc.mesh) {
        const uint64_t texels = 2ull * desc.mesh->domainCount();
        const uint32_t limit = mDevice->properties().limits.maxTexelBufferElements;
        if (texels > limit)
            return fail("createSubdiv: ", desc.mesh->name, " has ", std::to_string(desc.mesh->domainCount()),
                        " domains, whose records need ", std::to_string(texels),
                        " texels, more than this device's maxTexelBufferElements (", std::to_string(limit), ")");
    }
    Result<backend::SubdivHandle> handle = BasicCharacterBackend::createSubdiv(desc);
    if (!handle) return handle;
    if (Status attached = attachSubdivResources(*findSubdiv(handle.value())); !attached) {
        destroySubdiv(handle.value());
        return attached.error();
    }
    return handle;
}

void EmulatedTerrainBackend::subdivPrePasses(GpuSubdiv& surface, const gpu::UniformSlice& uniforms) {
    recordSubdivRefine(surface);
    mSubdivSource = recordSubdivFactorPasses(surface, uniforms);
    if (const GpuSubdiv::Extension* extension = surface.extension())
        mReport.intermediateBytes += extension->bytes();
}

void EmulatedTerrainBackend::subdivDraw(GpuSubdiv& surface, const gpu::UniformSlice& uniforms) {
    mSubdivPass.record(*mFrame, surface, mSubdivSource, mPatternVertices, mFrameUniforms, uniforms,
                       mFrameInfo.wireframe);
    mSubdivSource = {};
}

void EmulatedTerrainBackend::beginFrame(const backend::FrameInfo& frame) {
    BasicCharacterBackend::beginFrame(frame);
    mCharacterPass.beginFrame(mFrame->slot());
}

void EmulatedTerrainBackend::drawCharacter(const CharacterInstance& instance, backend::CharacterPath path) {
    mCharacterPass.record(*mFrame, instance, path, mFrameInfo.wireframe, characterPush());
}

uint64_t EmulatedTerrainBackend::characterPassBytes() const {
    return mCharacterPass.bytes() + characterSkinBytes();
}

uint64_t EmulatedTerrainBackend::patternBytes() const {
    return mPatternVertices.size() + mKeyTable.size();
}

void EmulatedTerrainBackend::drawTessellated(GpuTerrain& terrain, const backend::TerrainDrawInfo& draw) {
    const bool continuous = draw.tessellation.mode == backend::TerrainMode::Continuous;
    const gpu::UniformSlice tessUniforms = pushTessUniforms(terrain, draw.tessellation, TS_EMU_MAX_LEVEL);
    EmulatedDrawSource source;
    if (!draw.visiblePatches.empty()) source = recordFactorPasses(terrain, draw, tessUniforms);
    mReport.intermediateBytes = patternBytes() + factorPassBytes();

    ensureMainPass();
    gpu::PassScope pass(*mFrame, continuous ? "terrain.continuous" : "terrain.adaptive");
    if (draw.visiblePatches.empty() || source.records == VK_NULL_HANDLE) return;
    VkCommandBuffer cmd = mFrame->cmd();
    const bool wire = mFrameInfo.wireframe && mWirePipeline.valid();
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, (wire ? mWirePipeline : mFillPipeline).handle());
    VkWriteDescriptorSet records{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    records.dstBinding = TS_BINDING_EMU_RECORDS;
    records.descriptorCount = 1;
    records.descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER;
    records.pTexelBufferView = &source.records;
    pushTerrainDescriptors(VK_PIPELINE_BIND_POINT_GRAPHICS, mLayout, terrain, {&records, 1});
    vkCmdPushConstants(cmd, mLayout.handle(), VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(uint32_t), &source.capacity);
    const VkBuffer patterns = mPatternVertices.handle();
    const VkDeviceSize offset = 0;
    vkCmdBindVertexBuffers(cmd, 0, 1, &patterns, &offset);
    // The emulated unit's output: five pattern pieces per superprimitive,
    // each an indirect command the backend's own passes wrote on the GPU.
    vkCmdDrawIndirect(cmd, source.commands, source.commandsOffset, source.capacity * TS_EMU_PIECES,
                      sizeof(VkDrawIndirectCommand));
    mReport.terrainPatchesDrawn += static_cast<uint32_t>(draw.visiblePatches.size());
    ++mReport.passes;
}

} // namespace tessera::backends
