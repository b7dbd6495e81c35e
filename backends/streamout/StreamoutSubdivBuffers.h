#pragma once
/// @file StreamoutSubdivBuffers.h
/// streamout's per-surface buffers for a subdivision surface, attached to
/// the surface (its TechniqueExtension): the records and commands its factor
/// pass streams out, one record per domain (EmulatedDrawSource.h). One set
/// per surface, not per frame slot: each pass waits for the previous draw's
/// reads with a barrier, as hulldomain's refine does on the refined points.

#include "common/EmulatedDrawSource.h"
#include "common/GpuSubdiv.h"
#include "common/TechniqueExtension.h"
#include "tessera/gpu/Buffer.h"
#include "tessera/gpu/BufferView.h"
#include "tessera/gpu/Device.h"

#include <cstdint>

namespace tessera::backends {

struct StreamoutSubdivBuffers final : TechniqueExtension {
    /// Buffers for `surface`'s domains, named "streamout.subdiv.<surface>.*".
    StreamoutSubdivBuffers(gpu::Device& device, const GpuSubdiv& surface);

    /// 2 * capacity RGBA32F texels: outer levels, then (inner, domain, 0).
    gpu::Buffer records;
    gpu::BufferView recordsView;
    /// 5 * capacity VkDrawIndirectCommand, every one written each frame.
    gpu::Buffer commands;
    uint32_t capacity = 0; ///< the surface's domains

    EmulatedDrawSource source() const { return {recordsView.handle(), capacity, commands.handle(), 0}; }
    uint64_t bytes() const override { return records.size() + commands.size(); }
};

} // namespace tessera::backends
