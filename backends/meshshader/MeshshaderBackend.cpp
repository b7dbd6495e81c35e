// meshshader: the D3D12-Ultimate-style backend (VK_EXT_mesh_shader). The
// fixed-function tessellator is gone: a compute pre-pass writes one level
// per control-mesh edge (shared with hulldomain), then task shaders read
// each visible patch's levels, cull it on its displaced bounds and launch
// one mesh workgroup per piece of its D3D11 pattern, and mesh shaders place
// and evaluate the piece's points, bit-exact with the hardware tessellator
// up to level 64 (TessMeshPattern.h). Characters take the same two passes
// as hulldomain's, the second through task and mesh shaders: compute skins
// the cage once into 128-bit compressed vertices, then a mesh workgroup per
// piece of each cage triangle's pattern evaluates Listing 8 at its points.
// Subdivision surfaces: the shared compute refine, then task shaders take
// each domain's levels (or cull it) and mesh shaders evaluate the surface at
// the pattern's points.
// Instanced crowds (MeshshaderCrowdPass): compute culls and bins into tier
// lists and skins the near slots (shared with hulldomain); the near tier
// goes through the character task and mesh shaders, an indirect mesh-task
// draw per creature; the middle and far tiers are meshlets (meshoptimizer)
// culled per instance in the task stage.
#include "common/BackendPlugin.h"
#include "common/BasicCharacterBackend.h"
#include "common/ComputeCharacterSkinPass.h"
#include "common/ComputeSubdivRefinePass.h"
#include "common/ComputeTessFactorPass.h"
#include "common/CrowdDescriptors.h"
#include "MeshshaderCharacterPass.h"
#include "MeshshaderCrowdPass.h"
#include "MeshshaderCrowdResources.h"
#include "MeshshaderSubdivPass.h"
#include "MeshshaderTerrainPass.h"

namespace tessera::backends {
namespace {

class MeshshaderBackend final : public BasicCharacterBackend {
protected:
    backend::BackendCapabilities describeCapabilities() const override {
        backend::BackendCapabilities caps;
        caps.name = "meshshader";
        caps.description = "D3D12-style: compute factor pre-pass, task and mesh shaders generating the patterns";
        caps.tessellation = backend::TessellationPath::Mesh;
        caps.usesCompute = true;
        caps.usesMeshShaders = true;
        caps.maxTessFactor = 64.0f;
        caps.terrainModes = 0b111;
        caps.subdiv = true;
        caps.crowd = true;
        caps.cascadedShadows = true;
        return caps;
    }

    // D3D12-class: the full look's terrain shading runs in compute, as on
    // hulldomain.
    TerrainResolvePass::Mode terrainResolveMode() const override { return TerrainResolvePass::Mode::Compute; }

    Status initializeTechnique(const backend::BackendInitInfo& info) override {
        mFactorPass = ComputeTessFactorPass(*mDevice, "meshshader");
        const auto color = static_cast<VkFormat>(info.colorFormat);
        const auto depth = static_cast<VkFormat>(info.depthFormat);
        mTerrainPass = MeshshaderTerrainPass(*mDevice, color, depth, mWireframeSupported);
        mCharacterSkin = ComputeCharacterSkinPass(*mDevice, "meshshader");
        mCharacterPatches = MeshshaderCharacterPass(*mDevice, color, depth, mWireframeSupported);
        mSubdivRefine = ComputeSubdivRefinePass(*mDevice, "meshshader");
        mSubdivPass = MeshshaderSubdivPass(*mDevice, color, depth, mWireframeSupported);
        mCrowdPass = MeshshaderCrowdPass(*mDevice, color, depth);
        return {};
    }

    void shutdownTechnique() override {
        mFactorPass = {};
        mTerrainPass = {};
        mCharacterSkin = {};
        mCharacterPatches = {};
        mSubdivRefine = {};
        mSubdivPass = {};
        mCrowdPass = {};
    }

    VkBufferUsageFlags subdivWriteUsage() const override { return VK_BUFFER_USAGE_STORAGE_BUFFER_BIT; }
    void recordSubdivPasses(GpuSubdiv& surface, const gpu::UniformSlice&) override {
        mSubdivRefine.record(*mFrame, surface, MeshshaderSubdivPass::kPointReaders);
    }
    void recordSubdivDraw(GpuSubdiv& surface, const gpu::UniformSlice& uniforms) override {
        mSubdivPass.recordDraw(*mFrame, surface, mFrameUniforms, uniforms, mFrameInfo.wireframe);
    }

    VkBufferUsageFlags compressedCageUsage() const override { return VK_BUFFER_USAGE_STORAGE_BUFFER_BIT; }
    void skinCharacter(const CharacterInstance& instance) override {
        mCharacterSkin.record(*mFrame, instance, characterPush(), VK_PIPELINE_STAGE_2_MESH_SHADER_BIT_EXT);
    }
    void drawCharacter(const CharacterInstance& instance, backend::CharacterPath path) override {
        mCharacterPatches.record(*mFrame, instance, path, mFrameInfo.wireframe, characterPush());
    }
    void drawCharacterShadow(const CharacterInstance& instance, backend::CharacterPath path,
                             const shader::ShadowCasterPush& caster) override {
        mCharacterPatches.recordShadow(*mFrame, instance, path, caster, characterPush());
    }

    // Instanced crowds: the lists, commands and near slots are storage
    // buffers written by compute (ComputeCrowdCullPass); the meshlets and the
    // task-shader commands are each crowd's own (MeshshaderCrowdResources).
    VkBufferUsageFlags crowdWriteUsage() const override { return VK_BUFFER_USAGE_STORAGE_BUFFER_BIT; }
    Status attachCrowdResources(GpuCrowd& crowd, backend::CrowdHandle handle,
                                const backend::CrowdDesc& desc) override {
        auto resources = MeshshaderCrowdResources::create(*mDevice, crowd, desc, handle.id);
        if (!resources) return resources.error();
        crowd.attach(std::move(resources.value()));
        return {};
    }
    void recordCrowdPasses(GpuCrowd& crowd, const CrowdFrame& frame) override {
        CrowdDescriptors descriptors(CrowdDescriptors::Mode::Storage, crowd, frame.slot, mFrameUniforms,
                                     frame.uniforms, mShadowMaps.writes());
        mCrowdPass.recordCompute(*mFrame, crowd, crowd.extensionAs<MeshshaderCrowdResources>(), descriptors,
                                 frame.instanceCount);
    }
    void recordCrowdDraws(GpuCrowd& crowd, const CrowdFrame& frame) override {
        CrowdDescriptors descriptors(CrowdDescriptors::Mode::Storage, crowd, frame.slot, mFrameUniforms,
                                     frame.uniforms, mShadowMaps.writes());
        mCrowdPass.recordDraws(*mFrame, crowd, crowd.extensionAs<MeshshaderCrowdResources>(), descriptors);
    }
    // The casters' task commands are written with the others in crowd.cull.
    void prepareCrowdShadow(GpuCrowd& /*crowd*/) override {}
    void recordCrowdShadow(GpuCrowd& crowd, const CrowdFrame& frame, const shader::ShadowCasterPush& caster) override {
        CrowdDescriptors descriptors(CrowdDescriptors::Mode::Storage, crowd, frame.slot, mFrameUniforms,
                                     frame.uniforms, mShadowMaps.writes());
        mCrowdPass.recordShadow(*mFrame, crowd, crowd.extensionAs<MeshshaderCrowdResources>(), descriptors,
                                caster);
    }
    // crowd.cull, crowd.skin and a draw pass per tier.
    uint32_t crowdPassCount() const override { return 2 + TS_LOD_TIERS; }

    void drawTessellated(GpuTerrain& terrain, const backend::TerrainDrawInfo& draw) override {
        const terrain::TessellationSettings& settings = draw.tessellation;
        const bool continuous = settings.mode == backend::TerrainMode::Continuous;
        const gpu::UniformSlice tessUniforms = pushTessUniforms(terrain, settings, 64.0f);
        // The technique's intermediates: the pre-pass's level buffers, one
        // pair per frame in flight, and the pattern tables.
        mReport.intermediateBytes += mTerrainPass.tableBytes();
        for (uint32_t slot = 0; slot < gpu::kFramesInFlight; ++slot)
            mReport.intermediateBytes += terrain.edgeLevels(slot).size() + terrain.patchLevels(slot).size();
        // Continuous mode has one level for the draw: no per-edge pre-pass.
        if (!continuous)
            mFactorPass.record(*mFrame, terrain, tessUniforms, terrainPush(terrain),
                               VK_PIPELINE_STAGE_2_TASK_SHADER_BIT_EXT);

        // Drawn when the main pass opens (drawTerrainInMainPass): its own
        // copy of the patches, which may outlive the caller's.
        drawTerrainInMainPass(settings.mode, static_cast<uint32_t>(draw.visiblePatches.size()),
                              [this, &terrain, tessUniforms,
                               patches = std::vector<uint32_t>(draw.visiblePatches.begin(), draw.visiblePatches.end())] {
                                  mTerrainPass.record(*mFrame, terrain, patches, tessUniforms, terrainPush(terrain),
                                                      mFrameInfo.wireframe);
                                  return true;
                              });
    }

private:
    ComputeTessFactorPass mFactorPass;
    MeshshaderTerrainPass mTerrainPass;
    ComputeCharacterSkinPass mCharacterSkin;
    MeshshaderCharacterPass mCharacterPatches;
    ComputeSubdivRefinePass mSubdivRefine;
    MeshshaderSubdivPass mSubdivPass;
    MeshshaderCrowdPass mCrowdPass;
};

} // namespace
} // namespace tessera::backends

TESSERA_REGISTER_PLUGIN(registry) {
    registry.registerBackend(tessera::backends::backendPlugin<tessera::backends::MeshshaderBackend>("meshshader"));
}
