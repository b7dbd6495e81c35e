#include "common/EmulatedTerrainBackend.h"

#include "common/CommandHelpers.h"
#include "common/TerrainBindings.h"
#include "tessera/shaders/FrameUniforms.h"
#include "tessera/shaders/TerrainUniforms.h"
#include "tessera/shaders/TessPattern.h"
#include "tessera/backend/SubdivMeshData.h"
#include "tessera/terrain/Terrain.h"
#include "tessera/tessellator/PatternLibrary.h"

#include "character.frag_crowd_texels.spv.h"
#include "crowd_impostor.frag_texels.spv.h"
#include "crowd_impostor.frag_texels_nearest.spv.h"
#include "crowd_impostor.vert_texels.spv.h"
#include "crowd_mesh.vert_texels.spv.h"
#include "crowd_mesh.vert_texels_shadow.spv.h"
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
    mLayout =
        terrainLayout(*mDevice, stages,
                      {{TS_BINDING_EMU_RECORDS, VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER, VK_SHADER_STAGE_VERTEX_BIT}},
                      sizeof(uint32_t), VK_SHADER_STAGE_VERTEX_BIT, name + ".terrainEmulated.layout");
    gpu::GraphicsPipelineDesc desc;
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
    mPipelines = FillWirePipelines(*mDevice, desc, name + ".terrainEmulated", mWireframeSupported);
    const auto color = static_cast<VkFormat>(info.colorFormat);
    const auto depth = static_cast<VkFormat>(info.depthFormat);
    mCharacterPass = EmulatedCharacterPass(*mDevice, name, color, depth, mWireframeSupported);
    if (Status factors = initializeFactorPasses(info); !factors) return factors;
    if (capabilities(nullptr).subdiv)
        mSubdivPass = EmulatedSubdivPass(*mDevice, name, color, depth, mWireframeSupported);
    if (capabilities(nullptr).crowd) {
        mCrowdMesh = CrowdMeshPass(*mDevice, CrowdDescriptors::Mode::Texels, crowd_mesh_vert_texels_spv,
                                   character_frag_crowd_texels_spv, color, depth, name + ".crowd.mesh",
                                   crowd_mesh_vert_texels_shadow_spv);
        mCrowdNear = EmulatedCrowdNearPass(*mDevice, color, depth, name);
        mCrowdImpostor = CrowdImpostorPass(*mDevice, CrowdDescriptors::Mode::Texels, crowd_impostor_vert_texels_spv,
                                           crowdImpostorFragment(*mDevice, crowd_impostor_frag_texels_spv,
                                                                 crowd_impostor_frag_texels_nearest_spv),
                                           color, depth, name + ".crowd.impostor");
    }
    return {};
}

void EmulatedTerrainBackend::shutdownTechnique() {
    shutdownFactorPasses();
    mCrowdNear = {};
    mCrowdMesh = {};
    mCrowdImpostor = {};
    mSubdivPass = {};
    mSubdivSource = {};
    mCharacterPass = {};
    mPipelines = {};
    mLayout = {};
    mKeyTable = {};
    mPatternVertices = {};
}

Status EmulatedTerrainBackend::checkTerrain(const backend::TerrainDesc& desc) {
    const uint64_t texels = 2ull * desc.terrain->grid().patchCount();
    const uint32_t limit = mDevice->properties().limits.maxTexelBufferElements;
    if (texels > limit)
        return fail("backend ", capabilities(nullptr).name, ": a terrain of ",
                    std::to_string(desc.terrain->grid().patchCount()), " patches needs ", std::to_string(texels),
                    " record texels, more than this device's maxTexelBufferElements (", std::to_string(limit), ")");
    return {};
}

Status EmulatedTerrainBackend::checkSubdiv(const backend::SubdivDesc& desc) {
    if (!desc.mesh) return {};
    const uint64_t texels = 2ull * desc.mesh->domainCount();
    const uint32_t limit = mDevice->properties().limits.maxTexelBufferElements;
    if (texels > limit)
        return fail("createSubdiv: ", desc.mesh->name, " has ", std::to_string(desc.mesh->domainCount()),
                    " domains, whose records need ", std::to_string(texels),
                    " texels, more than this device's maxTexelBufferElements (", std::to_string(limit), ")");
    return {};
}

void EmulatedTerrainBackend::recordSubdivPasses(GpuSubdiv& surface, const gpu::UniformSlice& uniforms) {
    recordSubdivRefine(surface);
    mSubdivSource = recordSubdivFactorPasses(surface, uniforms);
}

void EmulatedTerrainBackend::recordSubdivDraw(GpuSubdiv& surface, const gpu::UniformSlice& uniforms) {
    mSubdivPass.record(*mFrame, surface, mSubdivSource, mPatternVertices, mFrameUniforms, uniforms,
                       mFrameInfo.wireframe);
    mSubdivSource = {};
}

void EmulatedTerrainBackend::beginTechniqueFrame() {
    mCharacterPass.beginFrame(mFrame->slot());
}

void EmulatedTerrainBackend::recordCrowdDraws(GpuCrowd& crowd, const CrowdFrame& frame) {
    CrowdDescriptors descriptors(CrowdDescriptors::Mode::Texels, crowd, frame.slot, mFrameUniforms, frame.uniforms,
                                 mShadowMaps.writes());
    mCrowdNear.record(*mFrame, crowd, descriptors);
    mCrowdMesh.record(*mFrame, crowd, descriptors);
    mCrowdImpostor.record(*mFrame, crowd, descriptors);
}

void EmulatedTerrainBackend::recordCrowdShadow(GpuCrowd& crowd, const CrowdFrame& frame,
                                               const shader::ShadowCasterPush& caster) {
    CrowdDescriptors descriptors(CrowdDescriptors::Mode::Texels, crowd, frame.slot, mFrameUniforms, frame.uniforms,
                                 mShadowMaps.writes());
    // The impostor tier casts none (CrowdImpostorPass.h).
    mCrowdNear.recordShadow(*mFrame, crowd, descriptors, caster);
    mCrowdMesh.recordShadow(*mFrame, crowd, descriptors, caster);
}

void EmulatedTerrainBackend::drawCharacter(const CharacterInstance& instance, backend::CharacterPath path) {
    mCharacterPass.record(*mFrame, instance, path, mFrameInfo.wireframe, characterPush());
}

void EmulatedTerrainBackend::drawCharacterShadow(const CharacterInstance& instance, backend::CharacterPath path,
                                                 const shader::ShadowCasterPush& caster) {
    mCharacterPass.recordShadow(*mFrame, instance, path, caster, characterPush());
}

uint64_t EmulatedTerrainBackend::characterPassBytes() const {
    return mCharacterPass.bytes() + characterSkinBytes();
}

uint64_t EmulatedTerrainBackend::patternBytes() const {
    return mPatternVertices.size() + mKeyTable.size();
}

void EmulatedTerrainBackend::drawTessellated(GpuTerrain& terrain, const backend::TerrainDrawInfo& draw) {
    const gpu::UniformSlice tessUniforms = pushTessUniforms(terrain, draw.tessellation, TS_EMU_MAX_LEVEL);
    EmulatedDrawSource source;
    if (!draw.visiblePatches.empty()) source = recordFactorPasses(terrain, draw, tessUniforms);
    mReport.intermediateBytes += patternBytes() + factorPassBytes();

    const auto patches = static_cast<uint32_t>(draw.visiblePatches.size());
    drawTerrainInMainPass(draw.tessellation.mode, patches, [this, &terrain, source] {
        if (source.records == VK_NULL_HANDLE) return false;
        VkCommandBuffer cmd = mFrame->cmd();
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mPipelines.get(mFrameInfo.wireframe).handle());
        const VkWriteDescriptorSet records = texelWrite(TS_BINDING_EMU_RECORDS, &source.records);
        pushTerrainDescriptors(VK_PIPELINE_BIND_POINT_GRAPHICS, mLayout, terrain, {&records, 1});
        vkCmdPushConstants(cmd, mLayout.handle(), VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(uint32_t), &source.capacity);
        const VkBuffer patterns = mPatternVertices.handle();
        const VkDeviceSize offset = 0;
        vkCmdBindVertexBuffers(cmd, 0, 1, &patterns, &offset);
        // The emulated unit's output: five pattern pieces per superprimitive,
        // each an indirect command the backend's own passes wrote on the GPU.
        const uint32_t commands = source.commandCount ? source.commandCount : source.capacity * TS_EMU_PIECES;
        vkCmdDrawIndirect(cmd, source.commands, source.commandsOffset, commands, sizeof(VkDrawIndirectCommand));
        return true;
    });
}

} // namespace tessera::backends
