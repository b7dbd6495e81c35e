#include "GpuTerrain.h"

#include "tessera/terrain/HeightField.h"

#include <cassert>
#include <cstring>
#include <vector>

namespace tessera::backends {

GpuTerrain::GpuTerrain(gpu::Device& device, const backend::TerrainDesc& desc)
    : mTilesPerSide(desc.tilesPerSide), mQuadsPerTile(desc.quadsPerTile) {
    const terrain::HeightField& field = *desc.heightField;
    const float spacing = field.scale().horizontalSpacing;
    const glm::vec2 size = field.worldSize();
    mUniforms.worldSize = glm::vec4(size.x, size.y, field.scale().heightScale, spacing);
    mUniforms.heightTexel = glm::vec4(1.0f / float(field.width()), 1.0f / float(field.height()), float(field.width()),
                                      float(field.height()));
    mUniforms.tiling = glm::vec4(float(mTilesPerSide), float(mQuadsPerTile), size.x / float(mTilesPerSide), 0.0f);
    mUniformBuffer = gpu::Buffer(device, sizeof mUniforms, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, gpu::MemoryUsage::GpuOnly,
                                 "terrain.uniforms");
    mUniformBuffer.upload(std::span<const shader::TerrainUniforms>(&mUniforms, 1));

    gpu::ImageDesc image;
    image.width = field.width();
    image.height = field.height();
    image.format = VK_FORMAT_R16_UNORM;
    image.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    image.name = "terrain.heightMap";
    mHeightMap = gpu::Image(device, image);
    mHeightMap.upload(std::as_bytes(std::span(field.samples())), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    mSampler = gpu::Sampler(device, VK_FILTER_LINEAR, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, "terrain.heightSampler");

    // One tile's grid in tile-local [0,1]^2; instancing places it per tile.
    const uint32_t n = mQuadsPerTile;
    std::vector<glm::vec2> vertices;
    vertices.reserve((n + 1) * (n + 1));
    for (uint32_t j = 0; j <= n; ++j)
        for (uint32_t i = 0; i <= n; ++i) vertices.emplace_back(float(i) / float(n), float(j) / float(n));
    std::vector<uint32_t> indices;
    indices.reserve(n * n * 6);
    for (uint32_t j = 0; j < n; ++j) {
        for (uint32_t i = 0; i < n; ++i) {
            const uint32_t a = j * (n + 1) + i, b = a + 1, c = a + (n + 1), d = c + 1;
            indices.insert(indices.end(), {a, c, b, b, c, d});
        }
    }
    mGridIndexCount = static_cast<uint32_t>(indices.size());
    mGridVertices = gpu::Buffer(device, vertices.size() * sizeof(glm::vec2), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT,
                                gpu::MemoryUsage::GpuOnly, "terrain.gridVertices");
    mGridVertices.upload(std::span<const glm::vec2>(vertices));
    mGridIndices = gpu::Buffer(device, indices.size() * sizeof(uint32_t), VK_BUFFER_USAGE_INDEX_BUFFER_BIT,
                               gpu::MemoryUsage::GpuOnly, "terrain.gridIndices");
    mGridIndices.upload(std::span<const uint32_t>(indices));

    for (uint32_t s = 0; s < gpu::kFramesInFlight; ++s)
        mTileStreams[s] = gpu::Buffer(device, tileCount() * sizeof(uint32_t), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT,
                                      gpu::MemoryUsage::CpuToGpu, "terrain.visibleTiles" + std::to_string(s));
}

gpu::Buffer& GpuTerrain::writeVisibleTiles(uint32_t slot, std::span<const uint32_t> tiles) {
    assert(tiles.size() <= tileCount());
    gpu::Buffer& stream = mTileStreams[slot];
    std::memcpy(stream.mapped(), tiles.data(), tiles.size_bytes());
    return stream;
}

} // namespace tessera::backends
