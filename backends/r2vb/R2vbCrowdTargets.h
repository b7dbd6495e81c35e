#pragma once
/// @file R2vbCrowdTargets.h
/// One instanced crowd's render targets and small buffers for r2vb's culling
/// and LOD binning (layouts in shaders/R2vbCrowdLayout.h), sized once from
/// the crowd (maxIds, maxInstances, creatures, nearSlots x nearStride) and
/// checked against the device's largest render target at createCrowd, and
/// attached to the crowd (its TechniqueExtension). They are shared by the
/// frames in flight, as GpuCrowd's buffers are: the passes' barriers order
/// one frame's use after the last.

#include "common/GpuCrowd.h"
#include "common/TechniqueExtension.h"
#include "shaders/R2vbCrowdLayout.h"
#include "tessera/core/Result.h"
#include "tessera/gpu/Buffer.h"
#include "tessera/gpu/Device.h"
#include "tessera/gpu/Image.h"

#include <array>
#include <cstdint>
#include <memory>

namespace tessera::backends {

class R2vbCrowdTargets final : public TechniqueExtension {
public:
    /// The targets of `crowd`, named "r2vb.crowd<id>.<what>", or an error
    /// naming the device limit a target would exceed.
    static Result<std::unique_ptr<R2vbCrowdTargets>> create(gpu::Device& device, const GpuCrowd& crowd, uint32_t id);

    /// R32UI state targets, read and written in turn: stateRead() holds last
    /// frame's states, the other one receives this frame's.
    gpu::Image& state(uint32_t index) { return mState[index]; }
    uint32_t stateRead() const { return mStateRead; }
    /// After a frame's state pass: its target is the next frame's to read.
    void flipState() { mStateRead ^= 1u; }
    /// Whether the first read target still needs its tsLodStateNone() fill.
    bool stateCleared() const { return mStateCleared; }
    void setStateCleared() { mStateCleared = true; }

    /// The histogram pyramid: base side (a power of two), top level and the
    /// atlases of the even (0) and odd (1) levels (RGBA32UI).
    uint32_t pyramidSide() const { return mSide; }
    uint32_t pyramidTop() const { return mTop; }
    gpu::Image& pyramid(uint32_t parity) { return mPyramid[parity]; }

    /// Lists, u = tier * creatures + creature: per list its extraction draw
    /// (RGBA32UI) and its count (R32UI), one texel each, and the draws'
    /// indirect buffer (the first target copied).
    uint32_t listCount() const { return mLists; }
    gpu::Image& listDraws() { return mListDraws; }
    gpu::Image& listCounts() { return mListCounts; }
    gpu::Buffer& listDrawBuffer() { return mListDrawBuffer; }
    /// The compacted entries (RGBA32UI): list u's region starts at texel
    /// u * listRegionTexels(), whole rows.
    gpu::Image& entries() { return mEntries; }
    uint32_t listRegionTexels() const { return mRegionTexels; }

    /// Near slots: records and skin draws (RGBA32UI, texel s), the skin
    /// draws' indirect buffer, the commands and the compressed cages.
    gpu::Image& slotRecords() { return mSlotRecords; }
    gpu::Image& slotSkinDraws() { return mSlotSkinDraws; }
    gpu::Buffer& skinDrawBuffer() { return mSkinDrawBuffer; }
    gpu::Image& nearCommands() { return mNearCommands; }
    gpu::Image& nearCages() { return mNearCages; }

    /// Bytes of every target and buffer above.
    uint64_t bytes() const override { return mBytes; }

private:
    R2vbCrowdTargets() = default;

    std::array<gpu::Image, 2> mState;
    uint32_t mStateRead = 0;
    bool mStateCleared = false;
    uint32_t mSide = 1, mTop = 0;
    std::array<gpu::Image, 2> mPyramid;
    uint32_t mLists = 0, mRegionTexels = 0;
    gpu::Image mListDraws, mListCounts, mEntries;
    gpu::Buffer mListDrawBuffer;
    gpu::Image mSlotRecords, mSlotSkinDraws, mNearCommands, mNearCages;
    gpu::Buffer mSkinDrawBuffer;
    uint64_t mBytes = 0;
};

} // namespace tessera::backends
