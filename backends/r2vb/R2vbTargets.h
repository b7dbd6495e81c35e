#pragma once
/// @file R2vbTargets.h
/// One frame slot's render targets and buffers of the r2vb factor passes,
/// sized for a terrain's every patch so a frame never reallocates. The
/// layout of each target is in shaders/R2vbLayout.h.

#include "shaders/R2vbLayout.h"
#include "tessera/gpu/Buffer.h"
#include "tessera/gpu/BufferView.h"
#include "tessera/gpu/Device.h"
#include "tessera/gpu/Image.h"

#include <array>
#include <cstdint>

namespace tessera::backends {

class R2vbTargets {
public:
    /// Index of the outer-level and inner-level record targets among
    /// recordTargets(); the five command targets follow.
    static constexpr uint32_t kOuterTarget = 0;
    static constexpr uint32_t kInnerTarget = 1;
    static constexpr uint32_t kFirstCommandTarget = 2;

    R2vbTargets() = default;
    /// Targets and buffers for up to `patchCount` visible patches, named
    /// "r2vb.<what><slot>".
    R2vbTargets(gpu::Device& device, uint32_t patchCount, uint32_t slot);

    /// Visible patches these targets hold (0 before creation).
    uint32_t patchCapacity() const { return mPatchCapacity; }

    /// Rows of the cage and factor targets that `patches` visible patches fill.
    static uint32_t cageRows(uint32_t patches);
    /// Rows of the record and command targets that `patches` records fill.
    static uint32_t recordRows(uint32_t patches);

    /// RGBA32F: displaced corner and grid vertex ID per texel.
    gpu::Image& cage() { return mCage; }
    /// R32F: one edge level per texel.
    gpu::Image& factors() { return mFactors; }
    /// The factor target copied to a buffer: one vec4 of outer levels per
    /// visible patch, bound as a vertex stream.
    gpu::Buffer& factorStream() { return mFactorStream; }
    /// The command pass's seven colour attachments: outer levels (RGBA32F),
    /// inner levels and patch (RGBA32F), then one RGBA32UI per tessellator command.
    std::array<gpu::Image, R2VB_COMMAND_TARGETS>& recordTargets() { return mRecordTargets; }
    /// The records texel buffer (EmulatedTerrainBackend's contract) and its view.
    gpu::Buffer& records() { return mRecords; }
    const gpu::BufferView& recordView() const { return mRecordView; }
    /// The indirect buffer: five commands per record capacity.
    gpu::Buffer& commands() { return mCommands; }

    /// Bytes of every target and buffer above.
    uint64_t bytes() const { return mBytes; }

private:
    uint32_t mPatchCapacity = 0;
    uint64_t mBytes = 0;
    gpu::Image mCage;
    gpu::Image mFactors;
    gpu::Buffer mFactorStream;
    std::array<gpu::Image, R2VB_COMMAND_TARGETS> mRecordTargets;
    gpu::Buffer mRecords;
    gpu::BufferView mRecordView;
    gpu::Buffer mCommands;
};

} // namespace tessera::backends
