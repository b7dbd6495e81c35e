#pragma once
/// @file R2vbSubdivTargets.h
/// r2vb's per-surface render targets and buffers for a subdivision surface,
/// attached to the surface (its TechniqueExtension):
///   points   RGBA32F, pointsWidth() wide: texel i = refined point i (2D, as
///            a D3D9 render target must be), copied into the surface's
///            refined points (the R2VB step);
///   records  the command pass's seven targets, R2VB_RECORD_WIDTH wide,
///            texel r = domain r (R2vbLayout.h), copied into the records
///            texel buffer and the indirect buffer (EmulatedDrawSource.h).
/// One set per surface, not per frame slot: every pass waits for the
/// previous draw's reads with a barrier.

#include "common/EmulatedDrawSource.h"
#include "common/GpuSubdiv.h"
#include "common/TechniqueExtension.h"
#include "shaders/R2vbLayout.h"
#include "tessera/core/Result.h"
#include "tessera/gpu/Buffer.h"
#include "tessera/gpu/BufferView.h"
#include "tessera/gpu/Device.h"
#include "tessera/gpu/Image.h"

#include <array>
#include <cstdint>
#include <memory>

namespace tessera::backends {

class R2vbSubdivTargets final : public TechniqueExtension {
public:
    /// Targets for `surface`, named "r2vb.subdiv.<surface>.*". Fails,
    /// naming the surface and the limit, when a target would exceed the
    /// device's maxImageDimension2D.
    static Result<std::unique_ptr<R2vbSubdivTargets>> create(gpu::Device& device, const GpuSubdiv& surface);

    gpu::Image& points() { return mPoints; }
    /// Rows of the points target the surface's refined points fill.
    uint32_t pointRows() const { return mPointRows; }
    std::array<gpu::Image, R2VB_COMMAND_TARGETS>& recordTargets() { return mRecordTargets; }
    uint32_t recordRows() const { return mRecordRows; }
    gpu::Buffer& records() { return mRecords; }
    gpu::Buffer& commands() { return mCommands; }
    /// Records the buffers hold: whole rows of R2VB_RECORD_WIDTH.
    uint32_t capacity() const { return mRecordRows * R2VB_RECORD_WIDTH; }
    EmulatedDrawSource source() const { return {mRecordView.handle(), capacity(), mCommands.handle(), 0}; }

    uint64_t bytes() const override { return mBytes; }

private:
    R2vbSubdivTargets() = default;

    uint64_t mBytes = 0;
    gpu::Image mPoints;
    uint32_t mPointRows = 0;
    std::array<gpu::Image, R2VB_COMMAND_TARGETS> mRecordTargets;
    uint32_t mRecordRows = 0;
    gpu::Buffer mRecords;
    gpu::BufferView mRecordView;
    gpu::Buffer mCommands;
};

} // namespace tessera::backends
