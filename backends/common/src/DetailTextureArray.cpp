#include "common/DetailTextureArray.h"

#include "tessera/core/MipChain.h"
#include "tessera/shaders/TerrainUniforms.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

namespace tessera::backends {

namespace {

const char* const kLayerNames[TS_DETAIL_LAYERS] = {"grass", "dirt", "rock", "snow"};

// Each material's average colour (sRGB bytes) for a terrain created without
// detail textures: the flat albedos the full look was tuned with.
const uint8_t kFlatColors[TS_DETAIL_LAYERS][4] = {
    {55, 81, 31, 255}, {80, 72, 50, 255}, {108, 103, 97, 255}, {231, 235, 241, 255}};

float toLinear(uint8_t v) {
    const float c = float(v) / 255.0f;
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

} // namespace

Result<DetailTextureArray> DetailTextureArray::create(gpu::Device& device, std::span<const Rgba8Image> layers) {
    std::vector<Rgba8Image> flat;
    if (layers.empty()) {
        for (const auto& color : kFlatColors) flat.push_back({1, 1, std::vector<uint8_t>(color, color + 4)});
        layers = flat;
    }
    if (layers.size() != TS_DETAIL_LAYERS)
        return fail("terrain detail textures: expected ", std::to_string(TS_DETAIL_LAYERS),
                    " (grass, dirt, rock, snow), got ", std::to_string(layers.size()));
    const uint32_t size = layers[0].width;
    for (size_t i = 0; i < layers.size(); ++i) {
        const Rgba8Image& image = layers[i];
        if (image.width != size || image.height != size || (size & (size - 1)) != 0 ||
            image.pixels.size() != size_t(size) * size * 4)
            return fail("terrain detail texture ", kLayerNames[i], ": ", std::to_string(image.width), "x",
                        std::to_string(image.height), ", expected square power-of-two images of one size (",
                        std::to_string(size), "x", std::to_string(size), ")");
    }

    const uint32_t mips = core::mipLevelCount(size, size);
    // Every level of every layer, packed level by level, layer by layer.
    std::vector<std::byte> texels;
    std::vector<VkBufferImageCopy> regions;
    DetailTextureArray array;
    for (uint32_t layer = 0; layer < TS_DETAIL_LAYERS; ++layer) {
        std::vector<uint8_t> level = layers[layer].pixels;
        for (uint32_t mip = 0; mip < mips; ++mip) {
            const uint32_t side = std::max(1u, size >> mip);
            VkBufferImageCopy region{};
            region.bufferOffset = texels.size();
            region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, mip, layer, 1};
            region.imageExtent = {side, side, 1};
            regions.push_back(region);
            const auto* bytes = reinterpret_cast<const std::byte*>(level.data());
            texels.insert(texels.end(), bytes, bytes + level.size());
            if (side > 1) level = core::halveRgba8(level, side, side, core::MipEncoding::Srgb);
        }
        // The last level is the layer's 1x1 average.
        array.averages[layer] = glm::vec4(toLinear(level[0]), toLinear(level[1]), toLinear(level[2]), 1.0f);
    }
    gpu::ImageDesc desc;
    desc.width = size;
    desc.height = size;
    desc.format = VK_FORMAT_R8G8B8A8_SRGB;
    desc.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    desc.mipLevels = mips;
    desc.arrayLayers = TS_DETAIL_LAYERS;
    desc.name = "terrain.detailTextures";
    array.image = gpu::Image(device, desc);
    array.image.upload(texels, regions, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    return array;
}

} // namespace tessera::backends
