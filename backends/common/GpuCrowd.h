#pragma once
/// @file GpuCrowd.h
/// An instanced crowd's GPU resources, shared by the backends that draw
/// crowds (layouts in CrowdInstance.h): every creature's cage and far mesh
/// in one vertex and one index buffer, the baked clips, the LOD state per
/// instance id, the tier lists, the indirect commands, the near tier's
/// compressed-cage slots, and a ring of per-frame instance buffers.

#include "CrowdInstance.h"
#include "GpuCharacter.h"
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

class GpuCrowd {
public:
    /// One creature: its character (maps) and where its meshes sit.
    struct Creature {
        GpuCharacter* character = nullptr;
        uint32_t cageFirstVertex = 0, cageFirstIndex = 0, cageTriangles = 0;
        uint32_t farFirstVertex = 0, farFirstIndex = 0, farTriangles = 0;
    };

    /// `find` maps the desc's handles to the backend's characters.
    static Result<std::unique_ptr<GpuCrowd>> create(gpu::Device& device, const backend::CrowdDesc& desc,
                                                    const std::function<GpuCharacter*(backend::CharacterHandle)>& find);

    const std::vector<Creature>& creatures() const { return mCreatures; }
    uint32_t maxInstances() const { return mMaxInstances; }
    uint32_t maxIds() const { return mMaxIds; }
    uint32_t nearSlots() const { return mNearSlots; }
    uint32_t nearStride() const { return mNearStride; }
    uint32_t clipCount() const { return mClipCount; }

    gpu::Buffer& vertices() { return mVertices; }
    gpu::Buffer& indices() { return mIndices; }
    gpu::Buffer& bakedMatrices() { return mBaked; }
    VkBufferView bakedView() const { return mBakedView.handle(); }
    gpu::Buffer& clips() { return mClips; }
    gpu::Buffer& state() { return mState; }
    gpu::Buffer& lists() { return mLists; }
    gpu::Buffer& args() { return mArgs; }
    gpu::Buffer& nearCages() { return mNear; }
    gpu::Buffer& nearOwners() { return mNearOwners; }
    /// The frame slot's instance buffer (host-visible).
    gpu::Buffer& instances(uint32_t slot) { return mInstances[slot]; }
    /// The frame slot's copy of the indirect commands, read back when the
    /// slot comes round again (the tier counts of FrameReport).
    gpu::Buffer& argsReadback(uint32_t slot) { return mArgsReadback[slot]; }
    bool argsWritten(uint32_t slot) const { return mArgsWritten[slot]; }
    void setArgsWritten(uint32_t slot) { mArgsWritten[slot] = true; }

    /// Copies the valid ones of `instances` (backend::crowdInstanceValid)
    /// into the frame slot's buffer and returns how many.
    uint32_t uploadInstances(uint32_t slot, std::span<const shader::CrowdInstance> instances);
    /// The uniform block for a frame.
    shader::CrowdUniforms uniforms(const backend::CrowdDrawInfo& draw, uint32_t instanceCount) const;
    /// The indirect commands as every frame starts them: each list's mesh,
    /// no instances; the near dispatch empty.
    const std::vector<uint32_t>& initialArgs() const { return mInitialArgs; }

    /// Whether the state still needs its first fill (TS_LOD_NONE for every id).
    bool stateCleared() const { return mStateCleared; }
    void setStateCleared() { mStateCleared = true; }

    /// Device bytes of everything above, for FrameReport::intermediateBytes.
    uint64_t bytes() const;

private:
    GpuCrowd() = default;

    std::vector<Creature> mCreatures;
    std::vector<float> mLevelPerPixel;
    uint32_t mMaxInstances = 0, mMaxIds = 0, mNearSlots = 0, mNearStride = 0, mClipCount = 0;
    gpu::Buffer mVertices, mIndices, mBaked, mClips, mState, mLists, mArgs, mNear, mNearOwners;
    gpu::BufferView mBakedView;
    std::array<gpu::Buffer, gpu::kFramesInFlight> mInstances;
    std::array<gpu::Buffer, gpu::kFramesInFlight> mArgsReadback;
    std::array<bool, gpu::kFramesInFlight> mArgsWritten{};
    std::vector<uint32_t> mInitialArgs;
    bool mStateCleared = false;
};

} // namespace tessera::backends
