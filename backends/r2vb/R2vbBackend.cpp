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
#include "EmulatedTerrainBackend.h"
#include "R2vbCagePass.h"
#include "R2vbCommandPass.h"
#include "R2vbFactorPass.h"
#include "R2vbCharacterSkinPass.h"
#include "R2vbTargets.h"
#include "tessera/backend/PluginApi.h"

#include <algorithm>
#include <array>
#include <memory>
#include <string>

namespace tessera::backends {
namespace {

class R2vbBackend final : public EmulatedTerrainBackend {
public:
    backend::BackendCapabilities capabilities(const backend::DeviceFeatures* device) override {
        backend::BackendCapabilities caps;
        caps.name = "r2vb";
        caps.description = "D3D9-style: render-to-vertex-buffer multipass, emulated tessellator";
        caps.tessellation = backend::TessellationPath::Emulated;
        caps.maxTessFactor = 14.99f;
        caps.terrainModes = 0b111;
        checkRequirements(device, caps);
        return caps;
    }

protected:
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
        return {};
    }

    void shutdownFactorPasses() override {
        for (auto& targets : mTargets) targets = {};
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
        const r2vb::PushBindings push = [&](const gpu::PipelineLayout& layout,
                                            std::span<const VkWriteDescriptorSet> extra) {
            pushTerrainDescriptors(VK_PIPELINE_BIND_POINT_GRAPHICS, layout, terrain, extra);
        };
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

private:
    /// The slot's targets, made (once per terrain size) large enough for every
    /// patch of a terrain of `patchCount` patches.
    R2vbTargets& targetsFor(uint32_t slot, uint32_t patchCount) {
        R2vbTargets& targets = mTargets[slot];
        if (targets.patchCapacity() >= patchCount) return targets;
        // An earlier draw of this frame may still use the old ones.
        auto old = std::make_shared<R2vbTargets>(std::move(targets));
        mDevice->deferDestroy([old]() mutable { old.reset(); });
        targets = R2vbTargets(*mDevice, patchCount, slot);
        return targets;
    }

    R2vbCagePass mCagePass;
    R2vbFactorPass mFactorPass;
    R2vbCommandPass mCommandPass;
    R2vbCharacterSkinPass mCharacterSkin;
    std::array<R2vbTargets, gpu::kFramesInFlight> mTargets;
};

backend::Backend* create() { return new R2vbBackend(); }
void destroy(backend::Backend* b) { delete b; }

} // namespace
} // namespace tessera::backends

TESSERA_REGISTER_PLUGIN(registry) {
    registry.registerBackend({"r2vb", &tessera::backends::create, &tessera::backends::destroy});
}
