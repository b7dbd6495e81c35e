// hulldomain: the D3D11-style backend. A compute pre-pass writes one
// tessellation level per control-mesh edge; tessellation control (hull) and
// evaluation (domain) shaders draw the patches with levels up to 64.
#include "BasicCharacterBackend.h"
#include "CharacterPatchPass.h"
#include "CharacterSkinPass.h"
#include "FrameUniforms.h"
#include "HulldomainCrowdPass.h"
#include "TessFactorPass.h"
#include "tessera/backend/PluginApi.h"

#include <cstring>
#include <memory>
#include <vector>

#include "terrain_basic.frag.spv.h"
#include "terrain_patch.tesc.spv.h"
#include "terrain_patch.tese.spv.h"
#include "terrain_patch.vert.spv.h"

namespace tessera::backends {
namespace {

class HulldomainBackend final : public BasicCharacterBackend {
public:
    backend::BackendCapabilities capabilities(const backend::DeviceFeatures* device) override {
        backend::BackendCapabilities caps;
        caps.name = "hulldomain";
        caps.description = "D3D11-style: compute factor pre-pass, tessellation control/evaluation shaders";
        caps.tessellation = backend::TessellationPath::Hardware;
        caps.usesCompute = true;
        caps.maxTessFactor = 64.0f;
        caps.terrainModes = 0b111;
        caps.crowd = true;
        checkRequirements(device, caps);
        return caps;
    }

protected:
    Status initializeTechnique(const backend::BackendInitInfo& info) override {
        mFactorPass = TessFactorPass(*mDevice, "hulldomain");
        mCharacterSkin = CharacterSkinPass(*mDevice);
        mCharacterPatches = CharacterPatchPass(*mDevice, static_cast<VkFormat>(info.colorFormat),
                                               static_cast<VkFormat>(info.depthFormat), mWireframeSupported);
        mCrowdPass = HulldomainCrowdPass(*mDevice, static_cast<VkFormat>(info.colorFormat),
                                         static_cast<VkFormat>(info.depthFormat));
        const VkShaderStageFlags graphics = VK_SHADER_STAGE_ALL_GRAPHICS;
        mLayout = gpu::PipelineLayout(*mDevice,
                                      {{TS_BINDING_FRAME, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, graphics},
                                       {TS_BINDING_TERRAIN, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, graphics},
                                       {TS_BINDING_HEIGHTMAP, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, graphics},
                                       {TS_BINDING_TESS, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, graphics},
                                       {TS_BINDING_EDGE_LEVELS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, graphics},
                                       {TS_BINDING_PATCH_LEVELS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, graphics}},
                                      0, 0, "hulldomain.terrainPatches.layout");
        gpu::GraphicsPipelineDesc desc;
        desc.name = "hulldomain.terrainPatches.fill";
        desc.layout = &mLayout;
        desc.stages = {{VK_SHADER_STAGE_VERTEX_BIT, terrain_patch_vert_spv},
                       {VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT, terrain_patch_tesc_spv},
                       {VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT, terrain_patch_tese_spv},
                       {VK_SHADER_STAGE_FRAGMENT_BIT, terrain_basic_frag_spv}};
        // One control point per patch: its index, per instance.
        desc.vertexBindings = {{0, sizeof(uint32_t), VK_VERTEX_INPUT_RATE_INSTANCE}};
        desc.vertexAttributes = {{0, 0, VK_FORMAT_R32_UINT, 0}};
        desc.topology = VK_PRIMITIVE_TOPOLOGY_PATCH_LIST;
        desc.patchControlPoints = 1;
        desc.cullMode = VK_CULL_MODE_NONE;
        desc.colorFormats = {static_cast<VkFormat>(info.colorFormat)};
        desc.depthFormat = static_cast<VkFormat>(info.depthFormat);
        mFillPipeline = gpu::Pipeline(*mDevice, desc);
        if (mWireframeSupported) {
            desc.name = "hulldomain.terrainPatches.wireframe";
            desc.polygonMode = VK_POLYGON_MODE_LINE;
            mWirePipeline = gpu::Pipeline(*mDevice, desc);
        }
        return {};
    }

    void shutdownTechnique() override {
        mFillPipeline = {};
        mWirePipeline = {};
        mLayout = {};
        mFactorPass = {};
        mCharacterSkin = {};
        mCharacterPatches = {};
        mCrowds.clear();
        mCrowdPass = {};
    }

public:
    Result<backend::CrowdHandle> createCrowd(const backend::CrowdDesc& desc) override {
        if (!mDevice) return fail("createCrowd before initialize");
        auto created = GpuCrowd::create(*mDevice, desc, [this](backend::CharacterHandle h) { return findCharacter(h); });
        if (!created) return created.error();
        mCrowds.push_back(std::move(created.value()));
        return backend::CrowdHandle{static_cast<uint32_t>(mCrowds.size() - 1)};
    }

    void destroyCrowd(backend::CrowdHandle handle) override {
        GpuCrowd* crowd = findCrowd(handle);
        if (!crowd) return;
        auto* released = mCrowds[handle.id].release();
        mDevice->deferDestroy([released] { delete released; });
    }

    void drawCrowd(backend::CrowdHandle handle, const backend::CrowdDrawInfo& draw) override {
        GpuCrowd* crowd = findCrowd(handle);
        if (!crowd) return;
        const uint32_t slot = mFrame->slot();
        reportCrowdCounts(*crowd, slot);
        const uint32_t count = crowd->uploadInstances(slot, draw.instances);
        const gpu::UniformSlice uniforms = mFrame->pushUniform(crowd->uniforms(draw, count));
        CrowdDescriptors descriptors(*crowd, slot, mFrameUniforms, uniforms);
        suspendMainPass();
        mCrowdPass.recordCompute(*mFrame, *crowd, descriptors, count);
        ensureMainPass();
        mCrowdPass.recordDraws(*mFrame, *crowd, descriptors);
        mReport.passes += 2 + TS_LOD_TIERS;
        mReport.intermediateBytes += crowd->bytes();
    }

    Result<backend::CrowdTiers> readCrowdTiers(backend::CrowdHandle handle) override {
        GpuCrowd* crowd = findCrowd(handle);
        if (!crowd) return fail("readCrowdTiers: no such crowd");
        mDevice->waitIdle();
        const VkDeviceSize listBytes = crowd->lists().size();
        const VkDeviceSize argBytes = TS_CROWD_ARG_WORDS * sizeof(uint32_t);
        gpu::Buffer readback(*mDevice, listBytes + argBytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                             gpu::MemoryUsage::GpuToCpu, "crowd.tierReadback");
        mDevice->submitImmediate(
            [&](VkCommandBuffer cmd) {
                const VkBufferCopy lists{0, 0, listBytes};
                const VkBufferCopy args{0, listBytes, argBytes};
                vkCmdCopyBuffer(cmd, crowd->lists().handle(), readback.handle(), 1, &lists);
                vkCmdCopyBuffer(cmd, crowd->args().handle(), readback.handle(), 1, &args);
            },
            "crowd.readTiers");
        const auto* bytes = static_cast<const uint8_t*>(readback.mapped());
        std::vector<uint32_t> argWords(TS_CROWD_ARG_WORDS);
        std::memcpy(argWords.data(), bytes + listBytes, argBytes);
        const auto* entries = reinterpret_cast<const shader::CrowdListEntry*>(bytes);
        backend::CrowdTiers tiers;
        for (uint32_t tier = 0; tier < TS_LOD_TIERS; ++tier)
            for (uint32_t c = 0; c < crowd->creatures().size(); ++c) {
                const uint32_t list = tier * TS_CROWD_MAX_CHARACTERS + c;
                const uint32_t n = std::min(argWords[list * TS_CROWD_ARG_DRAW_WORDS + 1], crowd->maxInstances());
                const uint32_t base = shader::tsCrowdListBase(tier, c, crowd->maxInstances());
                for (uint32_t k = 0; k < n; ++k) tiers.instances[tier].push_back(entries[base + k].instance);
            }
        return tiers;
    }

protected:

    VkBufferUsageFlags compressedCageUsage() const override { return VK_BUFFER_USAGE_STORAGE_BUFFER_BIT; }

    void skinCharacter(const CharacterInstance& instance) override {
        mCharacterSkin.record(*mFrame, instance, characterPush());
    }

    void drawCharacter(const CharacterInstance& instance, backend::CharacterPath path) override {
        mCharacterPatches.record(*mFrame, instance, path, mFrameInfo.wireframe, characterPush());
    }

    void drawTessellated(GpuTerrain& terrain, const backend::TerrainDrawInfo& draw) override {
        const terrain::TessellationSettings& settings = draw.tessellation;
        const bool continuous = settings.mode == backend::TerrainMode::Continuous;
        const gpu::UniformSlice tessUniforms = pushTessUniforms(terrain, settings, 64.0f);
        // The technique's intermediates: the pre-pass's level buffers, one
        // pair per frame in flight.
        mReport.intermediateBytes = 0;
        for (uint32_t slot = 0; slot < gpu::kFramesInFlight; ++slot)
            mReport.intermediateBytes += terrain.edgeLevels(slot).size() + terrain.patchLevels(slot).size();
        // Continuous mode has one level for the draw: no per-edge pre-pass.
        if (!continuous)
            mFactorPass.record(*mFrame, terrain, tessUniforms,
                               [this](VkPipelineBindPoint point, const gpu::PipelineLayout& layout, GpuTerrain& t,
                                      std::span<const VkWriteDescriptorSet> extra) {
                                   pushTerrainDescriptors(point, layout, t, extra);
                               });

        ensureMainPass();
        gpu::PassScope pass(*mFrame, continuous ? "terrain.continuous" : "terrain.adaptive");
        if (draw.visiblePatches.empty()) return;
        VkCommandBuffer cmd = mFrame->cmd();
        const bool wire = mFrameInfo.wireframe && mWirePipeline.valid();
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, (wire ? mWirePipeline : mFillPipeline).handle());
        const uint32_t slot = mFrame->slot();
        const VkDescriptorBufferInfo tessInfo = tessUniforms.descriptor();
        const VkDescriptorBufferInfo edgeLevels{terrain.edgeLevels(slot).handle(), 0, VK_WHOLE_SIZE};
        const VkDescriptorBufferInfo patchLevels{terrain.patchLevels(slot).handle(), 0, VK_WHOLE_SIZE};
        VkWriteDescriptorSet writes[3] = {};
        const std::pair<uint32_t, const VkDescriptorBufferInfo*> bindings[3] = {
            {TS_BINDING_TESS, &tessInfo}, {TS_BINDING_EDGE_LEVELS, &edgeLevels}, {TS_BINDING_PATCH_LEVELS, &patchLevels}};
        for (int i = 0; i < 3; ++i) {
            writes[i].sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
            writes[i].dstBinding = bindings[i].first;
            writes[i].descriptorCount = 1;
            writes[i].descriptorType = i == 0 ? VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
            writes[i].pBufferInfo = bindings[i].second;
        }
        pushTerrainDescriptors(VK_PIPELINE_BIND_POINT_GRAPHICS, mLayout, terrain, writes);
        gpu::Buffer& patchStream = terrain.writeVisiblePatches(slot, draw.visiblePatches);
        const VkBuffer buffers[1] = {patchStream.handle()};
        const VkDeviceSize offsets[1] = {0};
        vkCmdBindVertexBuffers(cmd, 0, 1, buffers, offsets);
        vkCmdDraw(cmd, 1, static_cast<uint32_t>(draw.visiblePatches.size()), 0, 0);
        mReport.terrainPatchesDrawn += static_cast<uint32_t>(draw.visiblePatches.size());
        ++mReport.passes;
    }

private:
    GpuCrowd* findCrowd(backend::CrowdHandle handle) {
        return handle.valid() && handle.id < mCrowds.size() ? mCrowds[handle.id].get() : nullptr;
    }

    // The tier counts the GPU wrote the last time this frame slot drew the
    // crowd (its fence has been waited for): FrameReport's crowd figures.
    void reportCrowdCounts(GpuCrowd& crowd, uint32_t slot) {
        if (!crowd.argsWritten(slot)) return;
        const auto* words = static_cast<const uint32_t*>(crowd.argsReadback(slot).mapped());
        for (uint32_t tier = 0; tier < TS_LOD_TIERS; ++tier)
            for (uint32_t c = 0; c < crowd.creatures().size(); ++c) {
                const uint32_t n = words[(tier * TS_CROWD_MAX_CHARACTERS + c) * TS_CROWD_ARG_DRAW_WORDS + 1];
                const GpuCrowd::Creature& k = crowd.creatures()[c];
                mReport.crowdInstances[tier] += n;
                mReport.crowdTriangles[tier] += uint64_t(n) * (tier == TS_LOD_FAR ? k.farTriangles : k.cageTriangles);
            }
    }

    TessFactorPass mFactorPass;
    HulldomainCrowdPass mCrowdPass;
    std::vector<std::unique_ptr<GpuCrowd>> mCrowds;
    CharacterSkinPass mCharacterSkin;
    CharacterPatchPass mCharacterPatches;
    gpu::PipelineLayout mLayout;
    gpu::Pipeline mFillPipeline;
    gpu::Pipeline mWirePipeline;
};

backend::Backend* create() { return new HulldomainBackend(); }
void destroy(backend::Backend* b) { delete b; }

} // namespace
} // namespace tessera::backends

TESSERA_REGISTER_PLUGIN(registry) {
    registry.registerBackend({"hulldomain", &tessera::backends::create, &tessera::backends::destroy});
}
