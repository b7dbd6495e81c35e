// hulldomain: the D3D11-style backend. A compute pre-pass writes one
// tessellation level per control-mesh edge; tessellation control (hull) and
// evaluation (domain) shaders draw the patches with levels up to 64.
#include "common/BackendPlugin.h"
#include "common/BasicCharacterBackend.h"
#include "common/CommandHelpers.h"
#include "common/ComputeCharacterSkinPass.h"
#include "common/ComputeSubdivRefinePass.h"
#include "common/ComputeTessFactorPass.h"
#include "common/CrowdDescriptors.h"
#include "common/FillWirePipelines.h"
#include "common/TerrainBindings.h"
#include "tessera/shaders/FrameUniforms.h"
#include "HulldomainCharacterPatchPass.h"
#include "HulldomainCrowdPass.h"
#include "HulldomainSubdivPass.h"

#include "hulldomain_terrain_patch.tesc.spv.h"
#include "hulldomain_terrain_patch.tese.spv.h"
#include "hulldomain_terrain_patch.vert.spv.h"
#include "terrain_basic.frag.spv.h"

namespace tessera::backends {
namespace {

class HulldomainBackend final : public BasicCharacterBackend {
protected:
    backend::BackendCapabilities describeCapabilities() const override {
        backend::BackendCapabilities caps;
        caps.name = "hulldomain";
        caps.description = "D3D11-style: compute factor pre-pass, tessellation control/evaluation shaders";
        caps.tessellation = backend::TessellationPath::Hardware;
        caps.usesCompute = true;
        caps.maxTessFactor = 64.0f;
        caps.terrainModes = 0b111;
        caps.crowd = true;
        caps.subdiv = true;
        caps.cascadedShadows = true;
        return caps;
    }

    // D3D11-class: the full look's terrain shading runs in compute, on every
    // core, after the main pass (tile-based deferred shading's place).
    TerrainResolvePass::Mode terrainResolveMode() const override { return TerrainResolvePass::Mode::Compute; }

    Status initializeTechnique(const backend::BackendInitInfo& info) override {
        mFactorPass = ComputeTessFactorPass(*mDevice, "hulldomain");
        mCharacterSkin = ComputeCharacterSkinPass(*mDevice, "hulldomain");
        mCharacterPatches = HulldomainCharacterPatchPass(*mDevice, static_cast<VkFormat>(info.colorFormat),
                                                         static_cast<VkFormat>(info.depthFormat), mWireframeSupported);
        mCrowdPass = HulldomainCrowdPass(*mDevice, static_cast<VkFormat>(info.colorFormat),
                                         static_cast<VkFormat>(info.depthFormat));
        mSubdivRefine = ComputeSubdivRefinePass(*mDevice, "hulldomain");
        mSubdivPass = HulldomainSubdivPass(*mDevice, static_cast<VkFormat>(info.colorFormat),
                                           static_cast<VkFormat>(info.depthFormat), mWireframeSupported);
        const VkShaderStageFlags graphics = VK_SHADER_STAGE_ALL_GRAPHICS;
        mLayout = terrainLayout(*mDevice, graphics,
                                {{TS_BINDING_TESS, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, graphics},
                                 {TS_BINDING_EDGE_LEVELS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, graphics},
                                 {TS_BINDING_PATCH_LEVELS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, graphics}},
                                0, 0, "hulldomain.terrainPatches.layout");
        gpu::GraphicsPipelineDesc desc;
        desc.layout = &mLayout;
        desc.stages = {{VK_SHADER_STAGE_VERTEX_BIT, hulldomain_terrain_patch_vert_spv},
                       {VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT, hulldomain_terrain_patch_tesc_spv},
                       {VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT, hulldomain_terrain_patch_tese_spv},
                       {VK_SHADER_STAGE_FRAGMENT_BIT, terrain_basic_frag_spv}};
        // One control point per patch: its index, per instance.
        desc.vertexBindings = {{0, sizeof(uint32_t), VK_VERTEX_INPUT_RATE_INSTANCE}};
        desc.vertexAttributes = {{0, 0, VK_FORMAT_R32_UINT, 0}};
        desc.topology = VK_PRIMITIVE_TOPOLOGY_PATCH_LIST;
        desc.patchControlPoints = 1;
        desc.cullMode = VK_CULL_MODE_NONE;
        desc.colorFormats = {static_cast<VkFormat>(info.colorFormat)};
        desc.depthFormat = static_cast<VkFormat>(info.depthFormat);
        mPipelines = FillWirePipelines(*mDevice, desc, "hulldomain.terrainPatches", mWireframeSupported);
        return {};
    }

    void shutdownTechnique() override {
        mPipelines = {};
        mLayout = {};
        mFactorPass = {};
        mCharacterSkin = {};
        mCharacterPatches = {};
        mCrowdPass = {};
        mSubdivRefine = {};
        mSubdivPass = {};
    }

    // Instanced crowds: the lists, commands and near slots are storage
    // buffers the compute passes write.
    VkBufferUsageFlags crowdWriteUsage() const override { return VK_BUFFER_USAGE_STORAGE_BUFFER_BIT; }
    void recordCrowdPasses(GpuCrowd& crowd, const CrowdFrame& frame) override {
        CrowdDescriptors descriptors(CrowdDescriptors::Mode::Storage, crowd, frame.slot, mFrameUniforms,
                                     frame.uniforms, mShadowMaps.writes());
        mCrowdPass.recordCompute(*mFrame, crowd, descriptors, frame.instanceCount);
    }
    void recordCrowdDraws(GpuCrowd& crowd, const CrowdFrame& frame) override {
        CrowdDescriptors descriptors(CrowdDescriptors::Mode::Storage, crowd, frame.slot, mFrameUniforms,
                                     frame.uniforms, mShadowMaps.writes());
        mCrowdPass.recordDraws(*mFrame, crowd, descriptors);
    }
    void recordCrowdShadow(GpuCrowd& crowd, const CrowdFrame& frame, const shader::ShadowCasterPush& caster) override {
        CrowdDescriptors descriptors(CrowdDescriptors::Mode::Storage, crowd, frame.slot, mFrameUniforms,
                                     frame.uniforms, mShadowMaps.writes());
        mCrowdPass.recordShadow(*mFrame, crowd, descriptors, caster);
    }
    uint32_t crowdPassCount() const override { return 2 + TS_LOD_TIERS; }

    VkBufferUsageFlags compressedCageUsage() const override { return VK_BUFFER_USAGE_STORAGE_BUFFER_BIT; }

    VkBufferUsageFlags subdivWriteUsage() const override { return VK_BUFFER_USAGE_STORAGE_BUFFER_BIT; }
    void recordSubdivPasses(GpuSubdiv& surface, const gpu::UniformSlice&) override {
        mSubdivRefine.record(*mFrame, surface, HulldomainSubdivPass::kPointReaders);
    }
    void recordSubdivDraw(GpuSubdiv& surface, const gpu::UniformSlice& uniforms) override {
        mSubdivPass.recordDraw(*mFrame, surface, mFrameUniforms, uniforms, mFrameInfo.wireframe);
    }

    void skinCharacter(const CharacterInstance& instance) override {
        mCharacterSkin.record(*mFrame, instance, characterPush(), VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT);
    }

    void drawCharacter(const CharacterInstance& instance, backend::CharacterPath path) override {
        mCharacterPatches.record(*mFrame, instance, path, mFrameInfo.wireframe, characterPush());
    }

    void drawCharacterShadow(const CharacterInstance& instance, backend::CharacterPath path,
                             const shader::ShadowCasterPush& caster) override {
        mCharacterPatches.recordShadow(*mFrame, instance, path, caster, characterPush());
    }

    void drawTessellated(GpuTerrain& terrain, const backend::TerrainDrawInfo& draw) override {
        const terrain::TessellationSettings& settings = draw.tessellation;
        const bool continuous = settings.mode == backend::TerrainMode::Continuous;
        const gpu::UniformSlice tessUniforms = pushTessUniforms(terrain, settings, 64.0f);
        // The technique's intermediates: the pre-pass's level buffers, one
        // pair per frame in flight.
        for (uint32_t slot = 0; slot < gpu::kFramesInFlight; ++slot)
            mReport.intermediateBytes += terrain.edgeLevels(slot).size() + terrain.patchLevels(slot).size();
        // Continuous mode has one level for the draw: no per-edge pre-pass.
        if (!continuous) mFactorPass.record(*mFrame, terrain, tessUniforms, terrainPush(terrain),
                                             VK_PIPELINE_STAGE_2_TESSELLATION_CONTROL_SHADER_BIT);

        // The patch stream is host memory of this frame slot: written now,
        // drawn when the main pass opens (drawTerrainInMainPass).
        const uint32_t slot = mFrame->slot();
        const auto patches = static_cast<uint32_t>(draw.visiblePatches.size());
        const VkBuffer patchStream =
            patches == 0 ? VK_NULL_HANDLE : terrain.writeVisiblePatches(slot, draw.visiblePatches).handle();
        drawTerrainInMainPass(settings.mode, patches, [this, &terrain, tessUniforms, slot, patches, patchStream] {
            VkCommandBuffer cmd = mFrame->cmd();
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mPipelines.get(mFrameInfo.wireframe).handle());
            const VkDescriptorBufferInfo tessInfo = tessUniforms.descriptor();
            const VkDescriptorBufferInfo edgeLevels{terrain.edgeLevels(slot).handle(), 0, VK_WHOLE_SIZE};
            const VkDescriptorBufferInfo patchLevels{terrain.patchLevels(slot).handle(), 0, VK_WHOLE_SIZE};
            const VkWriteDescriptorSet writes[3] = {
                bufferWrite(TS_BINDING_TESS, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, &tessInfo),
                bufferWrite(TS_BINDING_EDGE_LEVELS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, &edgeLevels),
                bufferWrite(TS_BINDING_PATCH_LEVELS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, &patchLevels)};
            pushTerrainDescriptors(VK_PIPELINE_BIND_POINT_GRAPHICS, mLayout, terrain, writes);
            const VkDeviceSize offset = 0;
            vkCmdBindVertexBuffers(cmd, 0, 1, &patchStream, &offset);
            vkCmdDraw(cmd, 1, patches, 0, 0);
            return true;
        });
    }

private:
    ComputeTessFactorPass mFactorPass;
    HulldomainCrowdPass mCrowdPass;
    ComputeSubdivRefinePass mSubdivRefine;
    HulldomainSubdivPass mSubdivPass;
    ComputeCharacterSkinPass mCharacterSkin;
    HulldomainCharacterPatchPass mCharacterPatches;
    gpu::PipelineLayout mLayout;
    FillWirePipelines mPipelines;
};

} // namespace
} // namespace tessera::backends

TESSERA_REGISTER_PLUGIN(registry) {
    registry.registerBackend(tessera::backends::backendPlugin<tessera::backends::HulldomainBackend>("hulldomain"));
}
