#pragma once
/// @file StreamoutBuffers.h
/// streamout's intermediate buffers, one set per frame slot so the CPU never
/// records over what a frame in flight reads. Transform feedback writes all
/// of them; they are sized for the largest terrain drawn so far.

#include "tessera/gpu/Buffer.h"
#include "tessera/gpu/BufferView.h"
#include "tessera/gpu/Device.h"

#include <array>
#include <cstdint>

namespace tessera::backends {

class StreamoutBuffers {
public:
    /// One frame slot's buffers.
    struct Slot {
        /// Transformed cage: one RGBA32F texel per grid vertex, (world xyz, vertex ID).
        gpu::Buffer cage;
        gpu::BufferView cageView;
        /// Indices of the patches that survived the GPU cull (uint each), read
        /// back as a vertex stream by the factor pass.
        gpu::Buffer survivors;
        /// Transform-feedback counter of the cull pass: bytes of survivors, the
        /// draw-auto vertex count.
        gpu::Buffer counter;
        /// Records as EmulatedTerrainBackend.h defines them: 2 * capacity RGBA32F
        /// texels (outer levels, then inner levels and patch index).
        gpu::Buffer records;
        gpu::BufferView recordsView;
        /// 5 * capacity VkDrawIndirectCommand, zero past the survivors.
        gpu::Buffer commands;
        uint32_t gridVertices = 0;
        uint32_t capacity = 0; ///< records (patches) the buffers hold
        /// GpuTerrain::heightRevision of the heights `cage` holds (0: none yet).
        uint64_t cageRevision = 0;
    };

    StreamoutBuffers() = default;
    explicit StreamoutBuffers(gpu::Device& device) : mDevice(&device) {}

    /// The slot's buffers, grown if needed to hold a terrain of
    /// `patchesPerSide` x `patchesPerSide` patches.
    Slot& prepare(uint32_t slot, uint32_t patchesPerSide);

    /// Bytes of every slot's buffers.
    uint64_t bytes() const;

private:
    void create(Slot& slot, uint32_t slotIndex, uint32_t patchesPerSide);

    gpu::Device* mDevice = nullptr;
    std::array<Slot, gpu::kFramesInFlight> mSlots;
};

} // namespace tessera::backends
