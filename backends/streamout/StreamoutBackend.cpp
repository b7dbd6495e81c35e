// streamout: the D3D10-style backend. Transform feedback, geometry-shader
// culling, draw-auto (vkCmdDrawIndirectByteCountEXT) and instanced draws
// with buffer loads, in front of the emulated tessellator; no tessellation
// stages and no compute. Each tessellated frame:
//   streamout.cage     the control mesh, displaced once, captured by transform feedback
//   streamout.cull     a geometry shader drops patches outside the frustum, streams out the rest
//   streamout.factors  draw-auto over the survivors: levels and tessellator commands, streamed out
// then EmulatedTerrainBackend draws the pattern pieces with one indirect draw.
// Subdivision surfaces (drawSubdiv) with the same means:
//   subdiv.refine      one point per refined point, its stencil over the cage,
//                      captured by transform feedback into the refined points
//   subdiv.factors     one point per domain: levels (tsSubdivLevels, clamped
//                      to 14.99), record and commands, streamed out
// then EmulatedSubdivPass draws the pattern pieces through subdiv_emulated.vert.
// Instanced crowds are culled and binned with the same means (the Froblins'
// D3D10 technique): a geometry shader culls the instances as points and
// streams the survivors out while rasterising their LOD state into a render
// target, successive stream-out passes sort them into the tier lists, and
// stream queries copied on the GPU give the indirect draws their counts
// (crowd.cull, crowd.bin, crowd.slots, crowd.skin; StreamoutCrowdRenderer.h).
#include "common/EmulatedTerrainBackend.h"

#include "tessera/gpu/Barriers.h"
#include "StreamoutBuffers.h"
#include "StreamoutCagePass.h"
#include "StreamoutCharacterSkinPass.h"
#include "StreamoutCrowdRenderer.h"
#include "StreamoutCullPass.h"
#include "StreamoutFactorPass.h"
#include "StreamoutRecording.h"
#include "StreamoutSubdivBuffers.h"
#include "StreamoutSubdivFactorPass.h"
#include "StreamoutSubdivRefinePass.h"
#include "tessera/backend/PluginApi.h"

#include <memory>

namespace tessera::backends {
namespace {

class StreamoutBackend final : public EmulatedTerrainBackend {
public:
    backend::BackendCapabilities capabilities(const device::DeviceFeatures* device) override {
        backend::BackendCapabilities caps;
        caps.name = "streamout";
        caps.description = "D3D10-style: transform feedback, geometry-shader culling, draw-auto, emulated tessellator";
        caps.tessellation = backend::TessellationPath::Emulated;
        caps.usesTransformFeedback = true;
        caps.usesGeometryShaders = true;
        caps.maxTessFactor = 14.99f;
        caps.terrainModes = 0b111;
        caps.crowd = true;
        caps.subdiv = true;
        checkRequirements(device, caps);
        return caps;
    }

protected:
    Status initializeFactorPasses(const backend::BackendInitInfo& info) override {
        if (Status limits = StreamoutFactorPass::checkDevice(*mDevice); !limits) return limits;
        mBuffers = StreamoutBuffers(*mDevice);
        mCagePass = StreamoutCagePass(*mDevice);
        mCullPass = StreamoutCullPass(*mDevice);
        mFactorPass = StreamoutFactorPass(*mDevice);
        mCharacterSkin = StreamoutCharacterSkinPass(*mDevice);
        mSubdivRefine = StreamoutSubdivRefinePass(*mDevice);
        mSubdivFactors = StreamoutSubdivFactorPass(*mDevice);
        mCrowds = std::make_unique<StreamoutCrowdRenderer>(*mDevice, static_cast<VkFormat>(info.colorFormat),
                                                           static_cast<VkFormat>(info.depthFormat));
        return {};
    }

    void shutdownFactorPasses() override {
        mCrowds.reset();
        mSubdivFactors = {};
        mSubdivRefine = {};
        mCharacterSkin = {};
        mFactorPass = {};
        mCullPass = {};
        mCagePass = {};
        mBuffers = {};
    }

    EmulatedDrawSource recordFactorPasses(GpuTerrain& terrain, const backend::TerrainDrawInfo& draw,
                                          const gpu::UniformSlice& tessUniforms) override {
        StreamoutBuffers::Slot& buffers = mBuffers.prepare(mFrame->slot(), terrain.patchesPerSide());
        const StreamoutPassInputs in{
            *mFrame, terrain, buffers, tessUniforms,
            [this, &terrain](const gpu::PipelineLayout& layout, std::span<const VkWriteDescriptorSet> extra) {
                pushTerrainDescriptors(VK_PIPELINE_BIND_POINT_GRAPHICS, layout, terrain, extra);
            }};
        // A terrain drawn earlier in this frame may still be reading these
        // buffers (its emulated draw, its passes): finish that before they
        // are cleared and streamed into again.
        gpu::memoryBarrier(
            mFrame->cmd(),
            VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_2_VERTEX_ATTRIBUTE_INPUT_BIT |
                VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_GEOMETRY_SHADER_BIT |
                VK_PIPELINE_STAGE_2_TRANSFORM_FEEDBACK_BIT_EXT,
            VK_ACCESS_2_TRANSFORM_FEEDBACK_WRITE_BIT_EXT | VK_ACCESS_2_TRANSFORM_FEEDBACK_COUNTER_WRITE_BIT_EXT,
            VK_PIPELINE_STAGE_2_TRANSFORM_FEEDBACK_BIT_EXT | VK_PIPELINE_STAGE_2_TRANSFER_BIT,
            VK_ACCESS_2_TRANSFORM_FEEDBACK_WRITE_BIT_EXT | VK_ACCESS_2_TRANSFORM_FEEDBACK_COUNTER_WRITE_BIT_EXT |
                VK_ACCESS_2_TRANSFER_WRITE_BIT);
        mCagePass.record(in);
        mCullPass.record(in, draw.visiblePatches);
        mFactorPass.record(in, emuKeyTable());
        return {buffers.recordsView.handle(), buffers.capacity, buffers.commands.handle(), 0};
    }

    uint64_t factorPassBytes() const override { return mBuffers.bytes(); }

    // The compressed cage is captured by transform feedback.
    VkBufferUsageFlags compressedCageUsage() const override {
        return VK_BUFFER_USAGE_TRANSFORM_FEEDBACK_BUFFER_BIT_EXT;
    }

    void skinCharacter(const CharacterInstance& instance) override {
        mCharacterSkin.record(*mFrame, instance, characterPush());
    }

    // Subdivision surfaces: the refined points are captured by transform
    // feedback, then a second stream-out pass writes records and commands.
    VkBufferUsageFlags subdivWriteUsage() const override { return VK_BUFFER_USAGE_TRANSFORM_FEEDBACK_BUFFER_BIT_EXT; }

    Status attachSubdivResources(GpuSubdiv& surface) override {
        surface.attach(std::make_unique<StreamoutSubdivBuffers>(*mDevice, surface));
        return {};
    }

    void recordSubdivRefine(GpuSubdiv& surface) override { mSubdivRefine.record(*mFrame, surface); }

    EmulatedDrawSource recordSubdivFactorPasses(GpuSubdiv& surface, const gpu::UniformSlice& uniforms) override {
        return mSubdivFactors.record(*mFrame, surface, uniforms, emuKeyTable());
    }

public:
    Result<backend::CrowdHandle> createCrowd(const backend::CrowdDesc& desc) override {
        if (!mCrowds) return Error{"createCrowd before initialize"};
        return mCrowds->create(desc, [this](backend::CharacterHandle h) { return findCharacter(h); });
    }

    void destroyCrowd(backend::CrowdHandle handle) override {
        if (mCrowds) mCrowds->destroy(handle);
    }

    void drawCrowd(backend::CrowdHandle handle, const backend::CrowdDrawInfo& draw) override {
        GpuCrowd* crowd = mCrowds ? mCrowds->find(handle) : nullptr;
        if (!crowd) return;
        const uint32_t slot = mFrame->slot();
        GpuCrowdSet::reportCounts(*crowd, slot, mReport);
        const uint32_t count = crowd->uploadInstances(slot, draw.instances);
        const gpu::UniformSlice uniforms = mFrame->pushUniform(crowd->uniforms(draw, count));
        suspendMainPass();
        mCrowds->recordPasses(*mFrame, handle, uniforms);
        GpuCrowdSet::recordCountsCopy(mFrame->cmd(), *crowd, slot);
        ensureMainPass();
        mCrowds->recordDraws(*mFrame, *crowd, mFrameUniforms, uniforms);
        mReport.passes += StreamoutCrowdRenderer::kPasses;
        mReport.intermediateBytes += mCrowds->bytes(handle);
        mReport.crowdBytes += mCrowds->bytes(handle);
    }

    Result<backend::CrowdTiers> readCrowdTiers(backend::CrowdHandle handle) override {
        if (!mCrowds) return Error{"readCrowdTiers: no such crowd"};
        return mCrowds->readTiers(handle);
    }

private:
    std::unique_ptr<StreamoutCrowdRenderer> mCrowds;
    StreamoutBuffers mBuffers;
    StreamoutCagePass mCagePass;
    StreamoutCullPass mCullPass;
    StreamoutFactorPass mFactorPass;
    StreamoutCharacterSkinPass mCharacterSkin;
    StreamoutSubdivRefinePass mSubdivRefine;
    StreamoutSubdivFactorPass mSubdivFactors;
};

backend::Backend* create() { return new StreamoutBackend(); }
void destroy(backend::Backend* b) { delete b; }

} // namespace
} // namespace tessera::backends

TESSERA_REGISTER_PLUGIN(registry) {
    registry.registerBackend({"streamout", &tessera::backends::create, &tessera::backends::destroy});
}
