#include "common/GpuTerrain.h"

#include <algorithm>
#include <atomic>
#include <cassert>
#include <cstring>

namespace tessera::backends {
namespace {

/// Process-wide, so a terrain made where a destroyed one lived never
/// inherits its revision (and a cache keyed on it).
uint64_t nextHeightRevision() {
    static std::atomic<uint64_t> next{1};
    return next++;
}

} // namespace

Result<std::unique_ptr<GpuTerrain>> GpuTerrain::create(gpu::Device& device, const terrain::Terrain& terrain,
                                                      std::span<const Rgba8Image> detailTextures) {
    VkFormatProperties props{};
    vkGetPhysicalDeviceFormatProperties(device.physical(), VK_FORMAT_R16_UNORM, &props);
    const VkFormatFeatureFlags needed = VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT | VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT |
                                        VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT |
                                        VK_FORMAT_FEATURE_TRANSFER_SRC_BIT | VK_FORMAT_FEATURE_TRANSFER_DST_BIT;
    VkFormatProperties bits{};
    vkGetPhysicalDeviceFormatProperties(device.physical(), VK_FORMAT_R16_UINT, &bits);
    const VkFormatFeatureFlags neededBits = VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT | VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT;
    if ((props.optimalTilingFeatures & needed) != needed || (bits.optimalTilingFeatures & neededBits) != neededBits)
        return fail("device ", device.features().deviceName,
                    " cannot render to and linearly sample R16_UNORM images (and their R16_UINT views), which the "
                    "terrain's dynamic height map needs");
    auto detail = DetailTextureArray::create(device, detailTextures);
    if (!detail) return detail.error();
    return std::make_unique<GpuTerrain>(device, terrain, std::move(detail.value()));
}

GpuTerrain::GpuTerrain(gpu::Device& device, const terrain::Terrain& terrain, DetailTextureArray detail)
    : mSource(terrain), mDetail(std::move(detail.image)), mHeightRevision(nextHeightRevision()) {
    const terrain::HeightField& field = terrain.field();
    const float spacing = field.scale().horizontalSpacing;
    const glm::vec2 size = field.worldSize();
    const glm::vec2 patch = terrain.grid().patchSize();
    mUniforms.worldSize = glm::vec4(size.x, size.y, field.scale().heightScale, spacing);
    mUniforms.heightTexel = glm::vec4(1.0f / float(field.width()), 1.0f / float(field.height()), float(field.width()),
                                      float(field.height()));
    mUniforms.tiling = glm::vec4(float(terrain.grid().patchesPerSide()), 0.0f, patch.x, patch.y);
    for (size_t i = 0; i < detail.averages.size(); ++i) mUniforms.detailAverage[i] = detail.averages[i];
    mUniformBuffer = gpu::Buffer(device, sizeof mUniforms, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, gpu::MemoryUsage::GpuOnly,
                                 "terrain.uniforms");
    mUniformBuffer.upload(std::span<const shader::TerrainUniforms>(&mUniforms, 1));

    gpu::ImageDesc image;
    image.width = field.width();
    image.height = field.height();
    image.format = VK_FORMAT_R16_UNORM;
    // A render target as well as a texture: craters are splatted into it
    // (TerrainSplatPass), the D3D9 way, which every backend can do.
    image.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                  VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
    image.aliasFormat = VK_FORMAT_R16_UINT; // exact integer writes for splats
    image.name = "terrain.heightMap";
    mHeightMap = gpu::Image(device, image);
    mHeightMap.upload(std::as_bytes(std::span(field.samples())), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    image.format = VK_FORMAT_R16_UINT; // read with texelFetch only
    image.aliasFormat = VK_FORMAT_UNDEFINED;
    image.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    image.name = "terrain.heightScratch";
    mHeightScratch = gpu::Image(device, image);
    mSampler = gpu::Sampler(device, VK_FILTER_LINEAR, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, "terrain.heightSampler");

    // Shadows are soft and filtered bilinearly, so a texel of up to two
    // height samples is enough and keeps the march's cost bounded.
    gpu::ImageDesc sun;
    sun.width = field.width();
    sun.height = field.height();
    while (sun.width > 1024 || sun.height > 1024) {
        sun.width = std::max(1u, sun.width / 2);
        sun.height = std::max(1u, sun.height / 2);
    }
    sun.format = VK_FORMAT_R8_UNORM;
    sun.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
    sun.name = "terrain.sunVisibility";
    mSunVisibility = gpu::Image(device, sun);
    // On a CPU rasterizer the detail textures were about a quarter of the
    // showcase's frame (lavapipe, 2 cores), half of it the second mip that
    // trilinear filtering reads; within the nearest mip the ground looks the
    // same at 1920 x 1080 (docs/LOOKS.md, "Detail textures on a CPU
    // rasterizer"). A GPU filters trilinearly for free.
    mDetailSampler = gpu::Sampler(device, VK_FILTER_LINEAR,
                                  device.features().isCpu ? VK_SAMPLER_MIPMAP_MODE_NEAREST
                                                          : VK_SAMPLER_MIPMAP_MODE_LINEAR,
                                  VK_SAMPLER_ADDRESS_MODE_REPEAT, "terrain.detailSampler");

    const glm::vec2 quad[4] = {{0.0f, 0.0f}, {1.0f, 0.0f}, {0.0f, 1.0f}, {1.0f, 1.0f}};
    const uint32_t indices[6] = {0, 2, 1, 1, 2, 3};
    mQuadVertices = gpu::Buffer(device, sizeof quad, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, gpu::MemoryUsage::GpuOnly,
                                "terrain.quadVertices");
    mQuadVertices.upload(std::span<const glm::vec2>(quad));
    mQuadIndices = gpu::Buffer(device, sizeof indices, VK_BUFFER_USAGE_INDEX_BUFFER_BIT, gpu::MemoryUsage::GpuOnly,
                               "terrain.quadIndices");
    mQuadIndices.upload(std::span<const uint32_t>(indices));

    // Per slot, so the CPU never writes what a frame in flight still reads.
    for (uint32_t s = 0; s < gpu::kFramesInFlight; ++s) {
        const std::string suffix = std::to_string(s);
        mSlots[s].patchStream = gpu::Buffer(device, patchCount() * sizeof(uint32_t),
                                            VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                            gpu::MemoryUsage::CpuToGpu, "terrain.visiblePatches" + suffix);
        mSlots[s].edgeErrors = gpu::Buffer(device, edgeCount() * sizeof(float), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                           gpu::MemoryUsage::CpuToGpu, "terrain.edgeErrors" + suffix);
        mSlots[s].patchErrors = gpu::Buffer(device, patchCount() * sizeof(float), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                            gpu::MemoryUsage::CpuToGpu, "terrain.patchErrors" + suffix);
        mSlots[s].edgeLevels = gpu::Buffer(device, edgeCount() * sizeof(float), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                           gpu::MemoryUsage::GpuOnly, "terrain.edgeLevels" + suffix);
        mSlots[s].patchLevels = gpu::Buffer(device, patchCount() * sizeof(float), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                            gpu::MemoryUsage::GpuOnly, "terrain.patchLevels" + suffix);
    }
}

bool GpuTerrain::sunVisibilityStale(const glm::vec3& sun) const {
    // A sun that moved less than ~0.06 degrees casts the same shadows.
    return !mSunVisibilityValid || glm::dot(sun, mSunVisibilityFor) < 0.9999995f;
}

void GpuTerrain::markSunVisibility(const glm::vec3& sun) {
    mSunVisibilityFor = sun;
    mSunVisibilityValid = true;
    mSunDirty.reset();
}

void GpuTerrain::invalidateSunVisibility(const glm::vec4& region) {
    if (!mSunDirty) mSunDirty = region;
    else
        mSunDirty = glm::vec4(glm::min(glm::vec2(*mSunDirty), glm::vec2(region)),
                              glm::max(glm::vec2(mSunDirty->z, mSunDirty->w), glm::vec2(region.z, region.w)));
}

void GpuTerrain::markHeightsChanged() { mHeightRevision = nextHeightRevision(); }

gpu::Buffer& GpuTerrain::writeVisiblePatches(uint32_t slot, std::span<const uint32_t> patches) {
    assert(patches.size() <= patchCount());
    gpu::Buffer& stream = mSlots[slot].patchStream;
    std::memcpy(stream.mapped(), patches.data(), patches.size_bytes());
    return stream;
}

void GpuTerrain::syncDetail(uint32_t slot) {
    Slot& s = mSlots[slot];
    if (s.detailRevision == mSource.revision()) return;
    const auto& detail = mSource.detail();
    std::memcpy(s.edgeErrors.mapped(), detail.edgeError().data(), detail.edgeError().size() * sizeof(float));
    std::memcpy(s.patchErrors.mapped(), detail.patchError().data(), detail.patchError().size() * sizeof(float));
    s.detailRevision = mSource.revision();
}

gpu::Buffer& GpuTerrain::edgeErrors(uint32_t slot) {
    syncDetail(slot);
    return mSlots[slot].edgeErrors;
}

gpu::Buffer& GpuTerrain::patchErrors(uint32_t slot) {
    syncDetail(slot);
    return mSlots[slot].patchErrors;
}

} // namespace tessera::backends
