// r2vb: the D3D9-style backend, after the first paper's DirectX 9 adaptive
// tessellation (Listings 13 to 16). Data goes round only through render
// targets, re-read by vertex texture fetch or copied to buffers and re-read
// as vertex streams (render to vertex buffer, R2VB); there is no compute, no
// storage write, no geometry or tessellation stage and no transform feedback.
// Each frame, for the visible patches:
//   r2vb.cage         the cage as points: each patch's four corners, displaced,
//                     with their grid vertex IDs, into an RGBA32F target;
//   r2vb.factors      one point per patch edge fetches its two corners from
//                     the cage, puts the lower vertex ID first (the paper's
//                     vertex-ID swap, so neighbours agree and there are no
//                     cracks) and writes the edge's level into an R32F target;
//   r2vb.copyFactors  R2VB: that target copied to a buffer, one vec4 of outer
//                     levels per patch;
//   r2vb.commands     one point per patch reads that stream, adds the inner
//                     levels and writes its record and the emulated
//                     tessellator's five indirect draw commands to seven
//                     render targets at once;
//   r2vb.copyRecords  R2VB: those targets copied to the record texel buffer
//                     and the indirect buffer;
// and EmulatedTerrainBackend draws the pattern pieces through the evaluation
// vertex shader. Continuous mode skips the first three: one level for all.
// The levels are those of hulldomain's compute pre-pass (terrain_metric.glsl),
// clamped to the emulated tessellator's 14.99.
//
// Subdivision surfaces (drawSubdiv), render targets only as well:
//   subdiv.refine      one point per refined point, its stencil over the
//                      cage, into an RGBA32F target (a texel per point);
//   subdiv.copyPoints  R2VB: the target copied into the refined points;
//   subdiv.commands    one point per domain: levels (tsSubdivLevels, clamped
//                      to 14.99), record and commands into seven targets;
//   subdiv.copyRecords R2VB: into the record texel buffer and indirect buffer;
// then EmulatedSubdivPass draws the pattern pieces through subdiv_emulated.vert.
//
// Instanced crowds (drawCrowd) are culled and binned the same way, with
// render targets only: R2vbCrowdBinningPass (the LOD state per id, a
// histogram pyramid over the creature-sorted instances, the lists' counts
// and the lists compacted by traversing it) and R2vbCrowdNearPass (near
// slots, their commands and skinned compressed cages); the tiers are then
// drawn by EmulatedTerrainBackend (EmulatedCrowdNearPass, CrowdMeshPass).
#include "common/BackendPlugin.h"
#include "common/EmulatedTerrainBackend.h"
#include "R2vbCagePass.h"
#include "R2vbCharacterSkinPass.h"
#include "R2vbCommandPass.h"
#include "R2vbCrowdBinningPass.h"
#include "R2vbCrowdNearPass.h"
#include "R2vbCrowdTargets.h"
#include "R2vbFactorPass.h"
#include "R2vbSubdivCommandPass.h"
#include "R2vbSubdivRefinePass.h"
#include "R2vbSubdivTargets.h"
#include "R2vbTargets.h"

#include <algorithm>
#include <array>
#include <memory>
#include <string>
#include <vector>

namespace tessera::backends {
namespace {

class R2vbBackend final : public EmulatedTerrainBackend {
protected:
    backend::BackendCapabilities describeCapabilities() const override {
        backend::BackendCapabilities caps;
        caps.name = "r2vb";
        caps.description = "D3D9-style: render-to-vertex-buffer multipass, emulated tessellator";
        caps.tessellation = backend::TessellationPath::Emulated;
        caps.maxTessFactor = 14.99f;
        caps.terrainModes = 0b111;
        caps.crowd = true;
        caps.cascadedShadows = true;
        caps.subdiv = true;
        return caps;
    }

    Status initializeFactorPasses(const backend::BackendInitInfo&) override {
        // The command pass writes a record's two texels and five commands at
        // once; every desktop driver and lavapipe have 8 attachments.
        const VkPhysicalDeviceLimits& limits = mDevice->properties().limits;
        if (limits.maxColorAttachments < R2VB_COMMAND_TARGETS ||
            limits.maxFragmentOutputAttachments < R2VB_COMMAND_TARGETS)
            return fail("backend r2vb needs ", std::to_string(R2VB_COMMAND_TARGETS),
                        " colour attachments in one pass; ", mDevice->features().deviceName, " has ",
                        std::to_string(std::min(limits.maxColorAttachments, limits.maxFragmentOutputAttachments)));
        mCagePass = R2vbCagePass(*mDevice);
        mFactorPass = R2vbFactorPass(*mDevice);
        mCommandPass = R2vbCommandPass(*mDevice);
        mCharacterSkin = R2vbCharacterSkinPass(*mDevice);
        mSubdivRefine = R2vbSubdivRefinePass(*mDevice);
        mSubdivCommands = R2vbSubdivCommandPass(*mDevice);
        mCrowdBinning = R2vbCrowdBinningPass(*mDevice);
        mCrowdNear = R2vbCrowdNearPass(*mDevice);
        return {};
    }

    void shutdownFactorPasses() override {
        mCrowdNear = {};
        mCrowdBinning = {};
        for (auto& targets : mTargets) targets = {};
        mSubdivCommands = {};
        mSubdivRefine = {};
        mCharacterSkin = {};
        mCommandPass = {};
        mFactorPass = {};
        mCagePass = {};
    }

    EmulatedDrawSource recordFactorPasses(GpuTerrain& terrain, const backend::TerrainDrawInfo& draw,
                                          const gpu::UniformSlice& tessUniforms) override {
        const uint32_t slot = mFrame->slot();
        R2vbTargets& targets = targetsFor(slot, terrain.patchCount());
        const uint32_t patches = static_cast<uint32_t>(draw.visiblePatches.size());
        const gpu::Buffer& patchStream = terrain.writeVisiblePatches(slot, draw.visiblePatches);
        const PushTerrainBindings push = terrainPush(terrain);
        // Continuous mode has one level for the draw: no cage, no per-edge levels.
        if (draw.tessellation.mode != backend::TerrainMode::Continuous) {
            mCagePass.record(*mFrame, targets, patchStream, patches, tessUniforms, push);
            mFactorPass.record(*mFrame, targets, patchStream, patches, terrain.edgeErrors(slot), tessUniforms, push);
        }
        const uint32_t capacity = mCommandPass.record(*mFrame, targets, patchStream, patches, terrain.patchErrors(slot),
                                                      emuKeyTable(), tessUniforms, push);
        return {targets.recordView().handle(), capacity, targets.commands().handle(), 0};
    }

    uint64_t factorPassBytes() const override {
        uint64_t bytes = 0;
        for (const auto& targets : mTargets) bytes += targets.bytes();
        return bytes;
    }

    uint64_t characterSkinBytes() const override { return mCharacterSkin.bytes(); }

    // The compressed cage is the destination of the render target's copy.
    VkBufferUsageFlags compressedCageUsage() const override { return VK_BUFFER_USAGE_TRANSFER_DST_BIT; }

    void skinCharacter(const CharacterInstance& instance) override {
        mCharacterSkin.record(*mFrame, instance, characterPush());
    }

    // Subdivision surfaces: the refined points are the destination of the
    // points target's copy; records and commands come from render targets.
    VkBufferUsageFlags subdivWriteUsage() const override { return VK_BUFFER_USAGE_TRANSFER_DST_BIT; }

    Status attachSubdivResources(GpuSubdiv& surface) override {
        auto targets = R2vbSubdivTargets::create(*mDevice, surface);
        if (!targets) return targets.error();
        surface.attach(std::move(targets.value()));
        return {};
    }

    void recordSubdivRefine(GpuSubdiv& surface) override {
        mSubdivRefine.record(*mFrame, surface, surface.extensionAs<R2vbSubdivTargets>());
    }

    EmulatedDrawSource recordSubdivFactorPasses(GpuSubdiv& surface, const gpu::UniformSlice& uniforms) override {
        return mSubdivCommands.record(*mFrame, surface, surface.extensionAs<R2vbSubdivTargets>(), uniforms,
                                      emuKeyTable());
    }

    // Instanced crowds: lists, commands and near slots are the destinations
    // of the render targets' copies; the targets are each crowd's own.
    VkBufferUsageFlags crowdWriteUsage() const override { return VK_BUFFER_USAGE_TRANSFER_DST_BIT; }

    /// Fails, naming the limit, when the crowd's render targets would not
    /// fit this device (R2vbCrowdTargets).
    Status attachCrowdResources(GpuCrowd& crowd, backend::CrowdHandle handle, const backend::CrowdDesc&) override {
        auto targets = R2vbCrowdTargets::create(*mDevice, crowd, handle.id);
        if (!targets) return targets.error();
        crowd.attach(std::move(targets.value()));
        return {};
    }

    void recordCrowdPasses(GpuCrowd& crowd, const CrowdFrame& frame) override {
        R2vbCrowdTargets& targets = crowd.extensionAs<R2vbCrowdTargets>();
        r2vb::crowd::FrameInputs in;
        in.crowd = &crowd;
        in.targets = &targets;
        in.instanceCount = frame.instanceCount;
        in.slot = frame.slot;
        in.uniforms = frame.uniforms.descriptor();
        in.instances = crowd.instancesView(frame.slot);
        in.occluders = crowd.occludersView(frame.slot);
        in.constants.pyramid = glm::uvec4(targets.pyramidSide(), targets.pyramidTop(), 0u, targets.listRegionTexels());
        const std::vector<glm::uvec2>& ranges = crowd.creatureRanges(frame.slot);
        for (uint32_t c = 0; c < ranges.size() && c < TS_CROWD_MAX_CHARACTERS; ++c) {
            glm::uvec4& pair = in.constants.ranges[c / 2];
            pair[(c & 1u) * 2] = ranges[c].x;
            pair[(c & 1u) * 2 + 1] = ranges[c].y;
        }
        mCrowdBinning.record(*mFrame, in);
        mCrowdNear.record(*mFrame, in);
    }

    uint32_t crowdPassCount() const override {
        return R2vbCrowdBinningPass::kPasses + R2vbCrowdNearPass::kPasses + TS_LOD_TIERS;
    }

private:
    /// The slot's targets, made (once per terrain size) large enough for every
    /// patch of a terrain of `patchCount` patches.
    R2vbTargets& targetsFor(uint32_t slot, uint32_t patchCount) {
        R2vbTargets& targets = mTargets[slot];
        if (targets.patchCapacity() >= patchCount) return targets;
        // An earlier draw of this frame may still use the old ones.
        mDevice->deferRelease(std::move(targets));
        targets = R2vbTargets(*mDevice, patchCount, slot);
        return targets;
    }

    R2vbCagePass mCagePass;
    R2vbFactorPass mFactorPass;
    R2vbCommandPass mCommandPass;
    R2vbCharacterSkinPass mCharacterSkin;
    R2vbSubdivRefinePass mSubdivRefine;
    R2vbSubdivCommandPass mSubdivCommands;
    std::array<R2vbTargets, gpu::kFramesInFlight> mTargets;
    R2vbCrowdBinningPass mCrowdBinning;
    R2vbCrowdNearPass mCrowdNear;
};

} // namespace
} // namespace tessera::backends

TESSERA_REGISTER_PLUGIN(registry) {
    registry.registerBackend(tessera::backends::backendPlugin<tessera::backends::R2vbBackend>("r2vb"));
}
