#pragma once
/// @file GpuCrowd.h
/// An instanced crowd's GPU resources, shared by every backend's crowd
/// (layouts in CrowdInstance.h): every creature's cage and far mesh in one
/// vertex and one index buffer (with the impostor tier's card), the baked
/// clips, the impostor atlases, the tier lists (instance streams of the
/// middle, far and impostor draws), their indirect commands, the near
/// tier's compressed-cage slots, the emulated near tier's slot records,
/// commands and triangle patterns, and a ring of per-frame instance buffers.
/// Each backend's culling and binning technique writes the lists, commands
/// and slots through the usage it names at creation (storage, transform
/// feedback or transfer). The per-agent LOD state (crowd.lodState) is here
/// for a technique that updates it in place (hulldomain's compute); one
/// that cannot write it in place (streamout's stream-out, r2vb's render
/// targets) keeps its own copies,
/// with the rest of what it keeps per crowd, in its TechniqueExtension.

#include "common/TechniqueExtension.h"
#include "tessera/shaders/CrowdInstance.h"
#include "common/GpuCharacter.h"
#include "common/GpuImpostorAtlas.h"
#include "tessera/backend/CrowdDesc.h"
#include "tessera/core/Result.h"
#include "tessera/gpu/Buffer.h"
#include "tessera/gpu/BufferView.h"
#include "tessera/gpu/Device.h"
#include "tessera/gpu/FrameContext.h"

#include <array>
#include <functional>
#include <memory>
#include <vector>

namespace tessera::backends {

class GpuCrowd : public ExtensionSlot {
public:
    /// One creature: its character (maps) and where its meshes sit.
    struct Creature {
        GpuCharacter* character = nullptr;
        uint32_t cageFirstVertex = 0, cageFirstIndex = 0, cageTriangles = 0;
        /// The middle tier's triangles over the cage's vertices (its own, or
        /// CrowdCharacterDesc::middleIndices).
        uint32_t middleFirstIndex = 0, middleTriangles = 0;
        uint32_t farFirstVertex = 0, farFirstIndex = 0, farTriangles = 0;
        /// The far tier's shadow casters' triangles over the far mesh's
        /// vertices (its own, or CrowdCharacterDesc::farCasterIndices).
        uint32_t farCasterFirstIndex = 0, farCasterTriangles = 0;
        /// The impostor tier's card (TS_CROWD_IMPOSTOR_INDICES indices over
        /// its 4 corners, shared by every creature).
        uint32_t impostorFirstIndex = 0;
        /// Triangles tier `tier` draws per instance (before tessellation).
        uint32_t tierTriangles(uint32_t tier) const {
            switch (tier) {
            case TS_LOD_NEAR: return cageTriangles;
            case TS_LOD_MIDDLE: return middleTriangles;
            case TS_LOD_FAR: return farTriangles;
            default: return TS_CROWD_IMPOSTOR_INDICES / 3;
            }
        }
        /// First index of tier `tier`'s mesh in the crowd's index buffer.
        uint32_t tierFirstIndex(uint32_t tier) const {
            switch (tier) {
            case TS_LOD_NEAR: return cageFirstIndex;
            case TS_LOD_MIDDLE: return middleFirstIndex;
            case TS_LOD_FAR: return farFirstIndex;
            default: return impostorFirstIndex;
            }
        }
    };

    /// `find` maps the desc's handles to the backend's characters;
    /// `writeUsage` is how the backend's passes write the lists, the
    /// commands and the near slots (added to their buffers' usage).
    static Result<std::unique_ptr<GpuCrowd>> create(gpu::Device& device, const backend::CrowdDesc& desc,
                                                    const std::function<GpuCharacter*(backend::CharacterHandle)>& find,
                                                    VkBufferUsageFlags writeUsage);

    const std::vector<Creature>& creatures() const { return mCreatures; }
    uint32_t maxInstances() const { return mMaxInstances; }
    uint32_t maxIds() const { return mMaxIds; }
    uint32_t nearSlots() const { return mNearSlots; }
    uint32_t nearStride() const { return mNearStride; }
    uint32_t clipCount() const { return mClipCount; }
    /// Largest cage triangle count: a near slot's instance stride on the emulated backends.
    uint32_t triangleStride() const { return mTriangleStride; }

    gpu::Buffer& vertices() { return mVertices; }
    gpu::Buffer& indices() { return mIndices; }
    gpu::Buffer& bakedMatrices() { return mBaked; }
    VkBufferView bakedView() const { return mBakedView.handle(); }
    gpu::Buffer& clips() { return mClips; }
    gpu::Buffer& state() { return mState; }
    gpu::Buffer& lists() { return mLists; }
    gpu::Buffer& args() { return mArgs; }
    /// The middle and far tiers' shadow casters' indexed indirect commands,
    /// one per (tier, creature) at casterArgsOffset: each list's command with
    /// the casters' triangles (Creature::farCasterFirstIndex, over the far
    /// mesh's vertices); recordCasterArgs copies the frame's instance counts
    /// in.
    gpu::Buffer& casterArgs() { return mCasterArgs; }
    static VkDeviceSize casterArgsOffset(uint32_t tier, uint32_t creature) {
        return VkDeviceSize((tier - TS_LOD_MIDDLE) * TS_CROWD_MAX_CHARACTERS + creature) * TS_CROWD_ARG_DRAW_WORDS *
               sizeof(uint32_t);
    }
    /// Outside any rendering, after the frame's binning wrote args(): copies
    /// the middle and far lists' instance counts into casterArgs(), for the
    /// casters' indirect draws that follow.
    void recordCasterArgs(VkCommandBuffer cmd);
    /// The impostor tier's atlases and their sampler.
    const GpuImpostorAtlas& impostors() const { return mImpostors; }
    gpu::Buffer& nearCages() { return mNear; }
    gpu::Buffer& nearOwners() { return mNearOwners; }
    /// The emulated near tier: a CrowdNearSlot per slot, and per creature
    /// and slot an indexed indirect command (tsCrowdNearCommandBase).
    gpu::Buffer& nearSlotRecords() { return mNearSlotRecords; }
    gpu::Buffer& nearCommands() { return mNearCommands; }
    /// The triangle pattern library (TrianglePatternLibrary): point codes
    /// (a vertex stream) and indices.
    gpu::Buffer& patternCodes() { return mPatternCodes; }
    gpu::Buffer& patternIndices() { return mPatternIndices; }
    /// Texel views for the emulated backends' shaders.
    VkBufferView indicesView() const { return mIndicesView.handle(); }
    /// The middle and far tiers' baked vertex animation and its per-clip table.
    VkBufferView bakedVerticesView() const { return mBakedVerticesView.handle(); }
    VkBufferView clipMeshesView() const { return mClipMeshesView.handle(); }
    VkBufferView clipsView() const { return mClipsView.handle(); }
    VkBufferView nearCagesView() const { return mNearView.handle(); }
    VkBufferView nearSlotsView() const { return mNearSlotsView.handle(); }
    VkBufferView instancesView(uint32_t slot) const { return mInstancesView[slot].handle(); }
    /// The frame slot's horizon grid (R32F texels, CrowdDrawInfo::occluders),
    /// read by the culling passes at TS_BINDING_CROWD_OCCLUDERS.
    VkBufferView occludersView(uint32_t slot) const { return mOccludersView[slot].handle(); }
    /// The frame slot's instance buffer (host-visible), sorted by creature.
    gpu::Buffer& instances(uint32_t slot) { return mInstances[slot]; }
    /// Where creature c's instances lie in the frame slot's buffer: first
    /// and count (uploadInstances sorts them by creature, stably).
    const std::vector<glm::uvec2>& creatureRanges(uint32_t slot) const { return mRanges[slot]; }
    /// The host's index of the frame slot's instance i (as drawCrowd got them).
    uint32_t hostIndex(uint32_t slot, uint32_t i) const { return mHostIndex[slot][i]; }
    /// The frame slot's copy of the indirect commands, read back when the
    /// slot comes round again (the tier counts of FrameReport).
    gpu::Buffer& argsReadback(uint32_t slot) { return mArgsReadback[slot]; }
    bool argsWritten(uint32_t slot) const { return mArgsWritten[slot]; }
    void setArgsWritten(uint32_t slot) { mArgsWritten[slot] = true; }

    /// Copies the valid ones of `instances` (backend::crowdInstanceValid)
    /// into the frame slot's buffer, sorted by creature (stable), and returns
    /// how many.
    uint32_t uploadInstances(uint32_t slot, std::span<const shader::CrowdInstance> instances);
    /// Copies the frame's horizon grid (at most TS_CROWD_MAX_OCCLUDER_CELLS
    /// squared; CrowdDrawInfo::occluders) into the frame slot's buffer;
    /// false, copying nothing, when it is larger (the frame's uniforms must
    /// then turn occlusion off).
    bool uploadOccluders(uint32_t slot, std::span<const float> occluders);
    /// Maps lists of the last uploaded frame's instance indices back to the host's.
    backend::CrowdTiers toHostIndices(backend::CrowdTiers tiers) const;
    /// The frame slot uploadInstances filled last.
    uint32_t lastSlot() const { return mLastSlot; }
    /// The uniform block for a frame.
    shader::CrowdUniforms uniforms(const backend::CrowdDrawInfo& draw, uint32_t instanceCount) const;
    /// The indirect commands as frame slot `slot`'s frame starts them (set
    /// by uploadInstances): each list's mesh and region, no instances; the
    /// near dispatch empty.
    const std::vector<uint32_t>& initialArgs(uint32_t slot) const { return mInitialArgs[slot]; }
    /// The first entry of list (tier, creature) in lists() for the frame
    /// slot's instances (tsCrowdListBase over creatureRanges(slot)).
    uint32_t listBase(uint32_t slot, uint32_t tier, uint32_t creature) const {
        return shader::tsCrowdListBase(tier, mRanges[slot][creature].x, mMaxInstances);
    }

    /// Whether the state still needs its first fill (TS_LOD_NONE for every id).
    bool stateCleared() const { return mStateCleared; }
    void setStateCleared() { mStateCleared = true; }

    /// Device bytes of everything above (not the extension), for
    /// FrameReport::intermediateBytes.
    uint64_t bytes() const;

private:
    GpuCrowd() = default;

    std::vector<Creature> mCreatures;
    std::vector<float> mLevelPerPixel;
    uint32_t mMaxInstances = 0, mMaxIds = 0, mNearSlots = 0, mNearStride = 0, mClipCount = 0, mTriangleStride = 0;
    std::vector<uint32_t> mFarVertices; ///< per creature
    gpu::Buffer mVertices, mIndices, mBaked, mClips, mState, mLists, mArgs, mCasterArgs, mNear, mNearOwners;
    gpu::Buffer mNearSlotRecords, mNearCommands, mPatternCodes, mPatternIndices, mBakedVertices, mClipMeshes;
    gpu::BufferView mBakedView, mIndicesView, mClipsView, mNearView, mNearSlotsView, mBakedVerticesView,
        mClipMeshesView;
    GpuImpostorAtlas mImpostors;
    std::array<gpu::Buffer, gpu::kFramesInFlight> mInstances;
    std::array<gpu::BufferView, gpu::kFramesInFlight> mInstancesView;
    std::array<gpu::Buffer, gpu::kFramesInFlight> mOccluders;
    std::array<gpu::BufferView, gpu::kFramesInFlight> mOccludersView;
    std::array<std::vector<glm::uvec2>, gpu::kFramesInFlight> mRanges;
    std::array<std::vector<uint32_t>, gpu::kFramesInFlight> mHostIndex;
    std::array<gpu::Buffer, gpu::kFramesInFlight> mArgsReadback;
    std::array<bool, gpu::kFramesInFlight> mArgsWritten{};
    std::array<std::vector<uint32_t>, gpu::kFramesInFlight> mInitialArgs;
    std::vector<uint32_t> mChunkCounts; ///< uploadInstances' per chunk and creature counts, then first places
    bool mStateCleared = false;
    uint32_t mLastSlot = 0;
};

} // namespace tessera::backends
