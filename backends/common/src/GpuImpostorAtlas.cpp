#include "common/GpuImpostorAtlas.h"

#include "tessera/character/BakedAnimation.h"
#include "tessera/character/ImpostorAtlas.h"
#include "tessera/shaders/CrowdImpostor.h"

#include <algorithm>
#include <cstddef>
#include <span>
#include <vector>

namespace tessera::backends {
namespace {

/// One image's texels (mip by mip, creature by creature) and the copies of
/// them into its layers.
struct Staged {
    std::vector<std::byte> texels;
    std::vector<VkBufferImageCopy> regions;

    /// Appends `bytes` and returns their offset.
    VkDeviceSize append(std::span<const std::byte> bytes) {
        const VkDeviceSize at = texels.size();
        texels.insert(texels.end(), bytes.begin(), bytes.end());
        return at;
    }
    /// Copies `layers` layers of mip `mip` (side `side`) from `offset` to
    /// the image's layers from `firstLayer`.
    void copy(VkDeviceSize offset, uint32_t mip, uint32_t side, uint32_t firstLayer, uint32_t layers) {
        VkBufferImageCopy region{};
        region.bufferOffset = offset;
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, mip, firstLayer, layers};
        region.imageExtent = {side, side, 1};
        regions.push_back(region);
    }
};

/// How a creature's atlas maps onto its baked clips' layers: `direct` when
/// it holds a clip per baked clip (the rest pose first), `skipsRest` when it
/// holds its asset's clips only (character::bakeImpostors: baked clip k + 1
/// is atlas clip k, and the rest pose, which it does not bake, shows atlas
/// clip 0's first phase); unusable (clear layers) otherwise.
enum class Mapping { Clear, Direct, SkipsRest };

Mapping mappingOf(const character::ImpostorAtlas* atlas, uint32_t side, uint32_t bakedClips) {
    if (!atlas || atlas->size != side || atlas->albedo.size() != TS_IMPOSTOR_MIPS ||
        atlas->normal.size() != TS_IMPOSTOR_MIPS)
        return Mapping::Clear;
    for (uint32_t mip = 0; mip < TS_IMPOSTOR_MIPS; ++mip) {
        const size_t bytes = size_t(side >> mip) * (side >> mip) * 4 * atlas->layers;
        if (atlas->albedo[mip].size() != bytes || atlas->normal[mip].size() != bytes) return Mapping::Clear;
    }
    if (atlas->layers == bakedClips * TS_IMPOSTOR_PHASES) return Mapping::Direct;
    if (bakedClips > 1 && atlas->layers == (bakedClips - 1) * TS_IMPOSTOR_PHASES) return Mapping::SkipsRest;
    return Mapping::Clear;
}

/// The rectangle each view cell of `atlas` covers over all its layers
/// (tsImpostorPackBounds), written at creature `creature`'s words.
void coveredBounds(const character::ImpostorAtlas& atlas, uint32_t creature, std::span<uint32_t> out) {
    const uint32_t side = atlas.size, cell = TS_IMPOSTOR_CELL;
    const std::vector<uint8_t>& texels = atlas.albedo[0];
    for (uint32_t cy = 0; cy < TS_IMPOSTOR_VIEWS; ++cy)
        for (uint32_t cx = 0; cx < TS_IMPOSTOR_VIEWS; ++cx) {
            uint32_t x0 = cell, y0 = cell, x1 = 0, y1 = 0;
            for (uint32_t layer = 0; layer < atlas.layers; ++layer)
                for (uint32_t y = 0; y < cell; ++y) {
                    const size_t row = (size_t(layer) * side + cy * cell + y) * side + cx * cell;
                    for (uint32_t x = 0; x < cell; ++x) {
                        if (texels[(row + x) * 4 + 3] == 0) continue;
                        x0 = std::min(x0, x);
                        y0 = std::min(y0, y);
                        x1 = std::max(x1, x + 1);
                        y1 = std::max(y1, y + 1);
                    }
                }
            // A texel to spare each side: bilinear filtering and the smaller
            // mips spread the silhouette's edge that far.
            const uint32_t word = shader::tsCrowdImpostorBoundsWord(creature, glm::uvec2(cx, cy));
            out[word] = x1 == 0 ? 0u
                                : shader::tsImpostorPackBounds(x0 > 0 ? x0 - 1 : 0, y0 > 0 ? y0 - 1 : 0,
                                                               std::min(x1 + 1, cell), std::min(y1 + 1, cell));
        }
}

gpu::Image makeImage(gpu::Device& device, uint32_t side, uint32_t layers, VkFormat format, const Staged& staged,
                     const char* name) {
    gpu::ImageDesc desc;
    desc.width = side;
    desc.height = side;
    desc.format = format;
    // Copied from, too: the tests read the layers back.
    desc.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    desc.mipLevels = TS_IMPOSTOR_MIPS;
    // Always TS_IMPOSTOR_PHASES layers or more: the view is 2D_ARRAY, as the
    // shaders declare it.
    desc.arrayLayers = layers;
    desc.name = name;
    gpu::Image image(device, desc);
    image.upload(staged.texels, staged.regions, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    return image;
}

} // namespace

GpuImpostorAtlas GpuImpostorAtlas::create(gpu::Device& device, const backend::CrowdDesc& desc) {
    const character::BakedAnimation& baked = *desc.animation;
    const uint32_t creatures = uint32_t(desc.characters.size());
    const uint32_t fullSide = TS_IMPOSTOR_VIEWS * TS_IMPOSTOR_CELL;
    // Creature c's baked clips run from characterClipBase[c] to the next
    // creature's first.
    std::vector<uint32_t> first(creatures), clips(creatures);
    std::vector<Mapping> mappings(creatures);
    for (uint32_t c = 0; c < creatures; ++c) {
        first[c] = baked.characterClipBase[c];
        const uint32_t end = c + 1 < creatures ? baked.characterClipBase[c + 1] : uint32_t(baked.clips.size());
        clips[c] = end > first[c] ? end - first[c] : 0u;
        mappings[c] = mappingOf(desc.characters[c].impostor, fullSide, clips[c]);
    }
    // Each creature's layers in turn, a baked clip's first layer where its
    // phases start: the rest pose (never baked by bakeImpostors) shows its
    // creature's first clip, with no layers of its own.
    GpuImpostorAtlas a;
    a.mFirstLayers.assign(baked.clips.size(), 0u);
    std::vector<uint32_t> creatureLayer(creatures, 0u);
    uint32_t layers = 0;
    for (uint32_t c = 0; c < creatures; ++c) {
        creatureLayer[c] = layers;
        if (mappings[c] == Mapping::Clear) continue;
        for (uint32_t k = 0; k < clips[c]; ++k) {
            const uint32_t atlasClip = mappings[c] == Mapping::Direct ? k : (k == 0 ? 0u : k - 1);
            a.mFirstLayers[first[c] + k] = layers + atlasClip * TS_IMPOSTOR_PHASES;
        }
        layers += desc.characters[c].impostor->layers;
    }
    // With no atlas at all, one clip's clear layers as small as
    // TS_IMPOSTOR_MIPS levels allow, which every instance reads (coverage 0:
    // its cards show no pixel).
    const bool any = layers > 0;
    const uint32_t side = any ? fullSide : 1u << (TS_IMPOSTOR_MIPS - 1);
    if (!any) layers = TS_IMPOSTOR_PHASES;

    Staged albedo, normal;
    for (uint32_t mip = 0; mip < TS_IMPOSTOR_MIPS; ++mip) {
        const uint32_t mipSide = side >> mip;
        const size_t layerBytes = size_t(mipSide) * mipSide * 4;
        for (Staged* staged : {&albedo, &normal}) {
            if (!any) {
                const std::vector<std::byte> clear(layerBytes * layers, std::byte{0});
                staged->copy(staged->append(clear), mip, mipSide, 0, layers);
                continue;
            }
            for (uint32_t c = 0; c < creatures; ++c) {
                if (mappings[c] == Mapping::Clear) continue;
                const character::ImpostorAtlas& atlas = *desc.characters[c].impostor;
                const std::vector<uint8_t>& bytes = staged == &albedo ? atlas.albedo[mip] : atlas.normal[mip];
                const VkDeviceSize at = staged->append(std::as_bytes(std::span<const uint8_t>(bytes)));
                staged->copy(at, mip, mipSide, creatureLayer[c], atlas.layers);
            }
        }
    }
    for (uint32_t c = 0; c < creatures && c < TS_CROWD_MAX_CHARACTERS; ++c)
        if (mappings[c] != Mapping::Clear) coveredBounds(*desc.characters[c].impostor, c, a.mBounds);
    a.mAlbedo = makeImage(device, side, layers, VK_FORMAT_R8G8B8A8_SRGB, albedo, "crowd.impostorAlbedo");
    a.mNormal = makeImage(device, side, layers, VK_FORMAT_R8G8B8A8_UNORM, normal, "crowd.impostorNormal");
    a.mSampler = gpu::Sampler(device, VK_FILTER_LINEAR, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, "crowd.impostorSampler");
    uint64_t mipTexels = 0;
    for (uint32_t mip = 0; mip < TS_IMPOSTOR_MIPS; ++mip) mipTexels += uint64_t(side >> mip) * (side >> mip);
    a.mBytes = 2 * 4 * mipTexels * layers;
    return a;
}

VkDescriptorImageInfo GpuImpostorAtlas::albedo() const {
    return {mSampler.handle(), mAlbedo.view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
}

VkDescriptorImageInfo GpuImpostorAtlas::normal() const {
    return {mSampler.handle(), mNormal.view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
}

} // namespace tessera::backends
