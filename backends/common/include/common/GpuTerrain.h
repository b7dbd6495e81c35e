#pragma once
/// @file GpuTerrain.h
/// A terrain's GPU resources shared by the backends: the dynamic height map
/// (the GPU copy of the height field, a render target so craters can be
/// splatted into it), its uniforms, the control mesh's quad, per-frame streams
/// of visible patch indices and the detail errors the adaptive metric reads.

#include "common/DetailTextureArray.h"
#include "tessera/shaders/TerrainUniforms.h"
#include "tessera/core/Result.h"
#include "tessera/gpu/Buffer.h"
#include "tessera/gpu/Device.h"
#include "tessera/gpu/Image.h"
#include "tessera/gpu/Sampler.h"
#include "tessera/terrain/Terrain.h"

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>

namespace tessera::backends {

class GpuTerrain {
public:
    /// Fails with a message when the device cannot render into a 16-bit
    /// height map (needed for splats) or sample it linearly.
    /// `detailTextures`: TerrainDesc::detailTextures (empty: flat colours).
    static Result<std::unique_ptr<GpuTerrain>> create(gpu::Device& device, const terrain::Terrain& terrain,
                                                      std::span<const Rgba8Image> detailTextures = {});

    GpuTerrain(gpu::Device& device, const terrain::Terrain& terrain, DetailTextureArray detail);

    const terrain::Terrain& source() const { return mSource; }
    uint32_t patchesPerSide() const { return mSource.grid().patchesPerSide(); }
    uint32_t patchCount() const { return mSource.grid().patchCount(); }
    uint32_t edgeCount() const { return mSource.grid().edgeCount(); }

    const shader::TerrainUniforms& uniforms() const { return mUniforms; }
    gpu::Buffer& uniformBuffer() { return mUniformBuffer; }
    /// R16_UNORM (with an R16_UINT alias view for splats),
    /// SHADER_READ_ONLY_OPTIMAL between passes.
    gpu::Image& heightMap() { return mHeightMap; }
    /// Same size, R16_UINT; holds the region a splat reads from.
    gpu::Image& heightScratch() { return mHeightScratch; }
    gpu::Sampler& sampler() { return mSampler; }
    /// The detail albedo array (DetailTextureArray), SHADER_READ_ONLY_OPTIMAL,
    /// and its trilinear repeating sampler.
    gpu::Image& detailTextures() { return mDetail; }
    gpu::Sampler& detailSampler() { return mDetailSampler; }
    /// R8_UNORM sun-visibility (horizon) map over the same extent as the
    /// height map, at most 1024 texels a side (TerrainSunPass renders it);
    /// SHADER_READ_ONLY_OPTIMAL once rendered.
    gpu::Image& sunVisibility() { return mSunVisibility; }
    /// Whether the whole map must be redrawn for `sun`: never drawn yet, or
    /// the sun moved.
    bool sunVisibilityStale(const glm::vec3& sun) const;
    /// World XZ rectangle (min x, min z, max x, max z) whose texels a crater
    /// may have changed since the map was drawn; empty when none.
    const std::optional<glm::vec4>& sunVisibilityDirty() const { return mSunDirty; }
    /// Records that the map now holds the visibility of `sun` everywhere.
    void markSunVisibility(const glm::vec3& sun);
    /// A crater changed the height map inside the world XZ rectangle
    /// `region` (min x, min z, max x, max z): the texels whose march towards
    /// the sun crosses it must be redrawn before the next draw.
    void invalidateSunVisibility(const glm::vec4& region);
    /// Changes whenever the height map does (made, or a crater splatted into
    /// it), and is never shared by two terrains: a technique that derives
    /// something from the heights alone (streamout's displaced cage) keeps it
    /// while this stays the same, instead of redoing it every frame.
    uint64_t heightRevision() const { return mHeightRevision; }
    /// A pass changed the height map (TerrainSplatPass).
    void markHeightsChanged();
    /// One control-mesh quad in patch-local [0,1]^2 (4 vertices, 6 indices),
    /// instanced once per visible patch for the untessellated draw.
    gpu::Buffer& quadVertices() { return mQuadVertices; }
    gpu::Buffer& quadIndices() { return mQuadIndices; }

    /// Writes this frame's visible patch indices into the slot's instance
    /// stream and returns the buffer to bind as a per-instance vertex stream
    /// (or, for the task stage, as a storage buffer).
    gpu::Buffer& writeVisiblePatches(uint32_t slot, std::span<const uint32_t> patches);

    /// The slot's copies of TerrainDetail's edge and patch errors (metres),
    /// refreshed when the terrain's revision changed since the slot last used them.
    gpu::Buffer& edgeErrors(uint32_t slot);
    gpu::Buffer& patchErrors(uint32_t slot);
    /// The slot's per-edge and per-patch tessellation levels, written on the
    /// GPU by a backend's factor pass and read by its tessellated draw.
    gpu::Buffer& edgeLevels(uint32_t slot) { return mSlots[slot].edgeLevels; }
    gpu::Buffer& patchLevels(uint32_t slot) { return mSlots[slot].patchLevels; }

private:
    void syncDetail(uint32_t slot);

    const terrain::Terrain& mSource;
    shader::TerrainUniforms mUniforms{};
    gpu::Buffer mUniformBuffer;
    gpu::Image mHeightMap;
    gpu::Image mHeightScratch;
    gpu::Sampler mSampler;
    gpu::Image mSunVisibility;
    gpu::Image mDetail;
    gpu::Sampler mDetailSampler;
    glm::vec3 mSunVisibilityFor{0.0f};
    bool mSunVisibilityValid = false;
    std::optional<glm::vec4> mSunDirty;
    uint64_t mHeightRevision = 0;
    gpu::Buffer mQuadVertices;
    gpu::Buffer mQuadIndices;
    struct Slot {
        gpu::Buffer patchStream;
        gpu::Buffer edgeErrors;
        gpu::Buffer patchErrors;
        gpu::Buffer edgeLevels;
        gpu::Buffer patchLevels;
        uint64_t detailRevision = UINT64_MAX;
    };
    std::array<Slot, gpu::kFramesInFlight> mSlots;
};

} // namespace tessera::backends
