// streamout: the D3D10-style backend. Transform feedback, geometry-shader
// culling, draw-auto (vkCmdDrawIndirectByteCountEXT) and instanced draws
// with buffer loads, in front of the emulated tessellator; no tessellation
// stages and no compute. Each tessellated frame:
//   streamout.cage     the control mesh, displaced once, captured by transform feedback
//                      (only when the height map changed since this frame slot's last capture)
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
// (crowd.cull, crowd.bin, crowd.slots, crowd.skin; StreamoutCrowdPasses.h),
// and EmulatedTerrainBackend draws the tiers.
#include "common/BackendPlugin.h"
#include "common/EmulatedTerrainBackend.h"

#include "tessera/gpu/Barriers.h"
#include "StreamoutBuffers.h"
#include "StreamoutCagePass.h"
#include "StreamoutCharacterSkinPass.h"
#include "StreamoutCrowdPasses.h"
#include "StreamoutCullPass.h"
#include "StreamoutFactorPass.h"
#include "StreamoutRecording.h"
#include "StreamoutSubdivBuffers.h"
#include "StreamoutSubdivFactorPass.h"
#include "StreamoutSubdivRefinePass.h"
#include "tessera/shaders/TessPattern.h"

#include <memory>

namespace tessera::backends {
namespace {

class StreamoutBackend final : public EmulatedTerrainBackend {
protected:
    backend::BackendCapabilities describeCapabilities() const override {
        backend::BackendCapabilities caps;
        caps.name = "streamout";
        caps.description = "D3D10-style: transform feedback, geometry-shader culling, draw-auto, emulated tessellator";
        caps.tessellation = backend::TessellationPath::Emulated;
        caps.usesTransformFeedback = true;
        caps.usesGeometryShaders = true;
        caps.maxTessFactor = 14.99f;
        caps.terrainModes = 0b111;
        caps.crowd = true;
        caps.cascadedShadows = true;
        caps.subdiv = true;
        return caps;
    }

    Status initializeFactorPasses(const backend::BackendInitInfo&) override {
        if (Status limits = StreamoutFactorPass::checkDevice(*mDevice); !limits) return limits;
        mBuffers = StreamoutBuffers(*mDevice);
        mCagePass = StreamoutCagePass(*mDevice);
        mCullPass = StreamoutCullPass(*mDevice);
        mFactorPass = StreamoutFactorPass(*mDevice);
        mCharacterSkin = StreamoutCharacterSkinPass(*mDevice);
        mSubdivRefine = StreamoutSubdivRefinePass(*mDevice);
        mSubdivFactors = StreamoutSubdivFactorPass(*mDevice);
        mCrowdPasses = std::make_unique<StreamoutCrowdPasses>(*mDevice);
        return {};
    }

    void shutdownFactorPasses() override {
        mCrowdPasses.reset();
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
        const StreamoutPassInputs in{*mFrame, terrain, buffers, tessUniforms, terrainPush(terrain)};
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
        // The displaced cage depends on the height map alone: this slot
        // re-streams it only when the heights changed (a new terrain, a
        // crater), not every frame. Its previous writer's barrier, recorded
        // on this queue before, already made it visible to the readers.
        if (buffers.cageRevision != terrain.heightRevision()) {
            mCagePass.record(in);
            buffers.cageRevision = terrain.heightRevision();
        }
        mCullPass.record(in, draw.visiblePatches);
        const auto visible = static_cast<uint32_t>(draw.visiblePatches.size());
        mFactorPass.record(in, emuKeyTable(), visible);
        // Records are streamed out one after another, at most one per visible
        // patch: the draw needs no command past those (not 5 per terrain patch).
        return {buffers.recordsView.handle(), buffers.capacity, buffers.commands.handle(), 0,
                visible * TS_EMU_PIECES};
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

    // Instanced crowds: lists, commands and near slots are captured by
    // transform feedback; the LOD state targets, queries and survivors are
    // each crowd's own (StreamoutCrowdResources).
    VkBufferUsageFlags crowdWriteUsage() const override { return VK_BUFFER_USAGE_TRANSFORM_FEEDBACK_BUFFER_BIT_EXT; }

    Status attachCrowdResources(GpuCrowd& crowd, backend::CrowdHandle, const backend::CrowdDesc&) override {
        auto resources = mCrowdPasses->createResources(crowd);
        if (!resources) return resources.error();
        crowd.attach(std::move(resources.value()));
        return {};
    }

    void recordCrowdPasses(GpuCrowd& crowd, const CrowdFrame& frame) override {
        mCrowdPasses->record(*mFrame, crowd, crowd.extensionAs<StreamoutCrowdResources>(), frame.uniforms);
    }

    uint32_t crowdPassCount() const override { return StreamoutCrowdPasses::kPasses + TS_LOD_TIERS; }

private:
    std::unique_ptr<StreamoutCrowdPasses> mCrowdPasses;
    StreamoutBuffers mBuffers;
    StreamoutCagePass mCagePass;
    StreamoutCullPass mCullPass;
    StreamoutFactorPass mFactorPass;
    StreamoutCharacterSkinPass mCharacterSkin;
    StreamoutSubdivRefinePass mSubdivRefine;
    StreamoutSubdivFactorPass mSubdivFactors;
};

} // namespace
} // namespace tessera::backends

TESSERA_REGISTER_PLUGIN(registry) {
    registry.registerBackend(tessera::backends::backendPlugin<tessera::backends::StreamoutBackend>("streamout"));
}
