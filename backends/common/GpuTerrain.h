#pragma once
/// @file GpuTerrain.h
/// A terrain's GPU resources shared by the backends: the dynamic height
/// texture, its uniforms, the tile grid mesh (the coarse control mesh drawn
/// in lowres mode) and per-frame streams of visible tile indices.

#include "TerrainUniforms.h"
#include "tessera/backend/TerrainDesc.h"
#include "tessera/gpu/Buffer.h"
#include "tessera/gpu/Device.h"
#include "tessera/gpu/Image.h"
#include "tessera/gpu/Sampler.h"

#include <array>
#include <cstdint>
#include <span>

namespace tessera::backends {

class GpuTerrain {
public:
    GpuTerrain(gpu::Device& device, const backend::TerrainDesc& desc);

    const shader::TerrainUniforms& uniforms() const { return mUniforms; }
    gpu::Buffer& uniformBuffer() { return mUniformBuffer; }
    gpu::Image& heightMap() { return mHeightMap; }
    gpu::Sampler& sampler() { return mSampler; }
    gpu::Buffer& gridVertices() { return mGridVertices; }
    gpu::Buffer& gridIndices() { return mGridIndices; }
    uint32_t gridIndexCount() const { return mGridIndexCount; }
    uint32_t tileCount() const { return mTilesPerSide * mTilesPerSide; }
    uint32_t quadsPerTile() const { return mQuadsPerTile; }

    /// Writes this frame's visible tile indices into the slot's instance
    /// stream and returns the buffer to bind as vertex binding 1.
    gpu::Buffer& writeVisibleTiles(uint32_t slot, std::span<const uint32_t> tiles);

private:
    shader::TerrainUniforms mUniforms{};
    gpu::Buffer mUniformBuffer;
    gpu::Image mHeightMap;
    gpu::Sampler mSampler;
    gpu::Buffer mGridVertices;
    gpu::Buffer mGridIndices;
    uint32_t mGridIndexCount = 0;
    uint32_t mTilesPerSide = 0;
    uint32_t mQuadsPerTile = 0;
    std::array<gpu::Buffer, gpu::kFramesInFlight> mTileStreams;
};

} // namespace tessera::backends
