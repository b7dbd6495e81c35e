#include "common/MipImage.h"

#include <algorithm>
#include <cstddef>

namespace tessera::backends {

gpu::Image makeMippedRgba8(gpu::Device& device, std::span<const std::span<const uint8_t>> layers, uint32_t width,
                           uint32_t height, VkFormat format, core::MipEncoding encoding, const std::string& name,
                           std::vector<std::array<uint8_t, 4>>* smallest) {
    gpu::ImageDesc desc;
    desc.width = width;
    desc.height = height;
    desc.format = format;
    desc.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    desc.mipLevels = core::mipLevelCount(width, height);
    desc.arrayLayers = uint32_t(layers.size());
    desc.name = name;
    // Every level of every layer, packed level by level, layer by layer.
    std::vector<std::byte> texels;
    std::vector<VkBufferImageCopy> regions;
    if (smallest) smallest->clear();
    for (uint32_t layer = 0; layer < desc.arrayLayers; ++layer) {
        std::vector<uint8_t> level(layers[layer].begin(), layers[layer].end());
        uint32_t w = width, h = height;
        for (uint32_t mip = 0; mip < desc.mipLevels; ++mip) {
            VkBufferImageCopy region{};
            region.bufferOffset = texels.size();
            region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, mip, layer, 1};
            region.imageExtent = {w, h, 1};
            regions.push_back(region);
            const auto* bytes = reinterpret_cast<const std::byte*>(level.data());
            texels.insert(texels.end(), bytes, bytes + level.size());
            if (mip + 1 == desc.mipLevels) break;
            level = core::halveRgba8(level, w, h, encoding);
            w = std::max(1u, w / 2);
            h = std::max(1u, h / 2);
        }
        if (smallest) smallest->push_back({level[0], level[1], level[2], level[3]});
    }
    gpu::Image image(device, desc);
    image.upload(texels, regions, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    return image;
}

} // namespace tessera::backends
