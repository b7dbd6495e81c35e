// The crowd's impostor atlases on the GPU (GpuImpostorAtlas) as the cards
// sample them: layer firstLayers()[ids.z] + k holds phase k of global baked
// clip ids.z, for every creature of a crowd and at every mip level,
// whichever layout its atlas has (a clip per baked clip, or its asset's
// clips only, the rest pose not baked and showing the first clip, as
// character::bakeImpostors makes it), no layer is stored twice, and a
// creature without an atlas has empty cards; under the validation layer.
#include "GpuTestDevice.h"
#include "SyntheticImpostorAtlas.h"

#include "common/GpuImpostorAtlas.h"
#include "tessera/character/BakedAnimation.h"
#include "tessera/gpu/Barriers.h"
#include "tessera/gpu/Buffer.h"
#include "tessera/gpu/Readback.h"

#include <gtest/gtest.h>

#include <cstring>
#include <vector>

using namespace tessera;
using namespace tessera::test;

TEST(GpuImpostorAtlas, TheLayersOfAGlobalClipHoldItsPhases) {
    std::string why;
    gpu::Device* device = GpuTestDevice::get(why);
    if (!device) GTEST_SKIP() << why;
    const uint64_t messagesBefore = GpuTestDevice::validationMessages();

    // Three creatures of three, three and two baked clips (the rest pose
    // first): an atlas of every baked clip, one of the asset's two clips
    // only, none.
    character::BakedAnimation baked;
    baked.clips.resize(8);
    baked.characterClipBase = {0, 3, 6};
    const character::ImpostorAtlas every = syntheticImpostorAtlas(0, 3, 1.0f, 1.5f);
    const character::ImpostorAtlas assetClips = syntheticImpostorAtlas(1, 2, 1.0f, 1.5f);
    std::vector<backend::CrowdCharacterDesc> characters(3);
    characters[0].impostor = &every;
    characters[1].impostor = &assetClips;
    backend::CrowdDesc desc;
    desc.characters = characters;
    desc.animation = &baked;
    const backends::GpuImpostorAtlas atlas = backends::GpuImpostorAtlas::create(*device, desc);

    // Only the atlases' own layers: 3 + 2 clips of 8 phases.
    const uint32_t layers = every.layers + assetClips.layers;
    ASSERT_EQ(layers, 5u * TS_IMPOSTOR_PHASES);
    const std::vector<uint32_t> firstLayers = {0, 8, 16, 24, 24, 32, 0, 0};
    EXPECT_EQ(atlas.firstLayers(), firstLayers);
    for (uint32_t cell = 0; cell < TS_IMPOSTOR_VIEWS * TS_IMPOSTOR_VIEWS; ++cell) {
        const uint32_t word = shader::tsCrowdImpostorBoundsWord(2, glm::uvec2(cell % 8, cell / 8));
        EXPECT_EQ(atlas.bounds()[word], 0u) << "the creature without an atlas has empty cards";
        EXPECT_NE(atlas.bounds()[shader::tsCrowdImpostorBoundsWord(0, glm::uvec2(cell % 8, cell / 8))], 0u);
    }
    const gpu::Image& image = atlas.albedoImage();
    ASSERT_EQ(image.arrayLayers(), layers);
    ASSERT_EQ(image.mipLevels(), TS_IMPOSTOR_MIPS);
    EXPECT_EQ(atlas.bytes(), 2ull * 4 * layers * (256 * 256 + 128 * 128 + 64 * 64 + 32 * 32));

    // The centre texel of cell (4, 4) of every layer, at mips 0 and 3.
    const uint32_t mips[2] = {0, TS_IMPOSTOR_MIPS - 1};
    const std::vector<std::byte> bytes = gpu::readBack(
        *device, VkDeviceSize(2) * layers * 4, "test.impostorAtlas.readback", "test.impostorAtlas.read",
        [&](VkCommandBuffer cmd, const gpu::Buffer& readback) {
            const VkImageMemoryBarrier2 toCopy[] = {gpu::imageBarrier(
                image, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_COPY_BIT,
                VK_ACCESS_2_TRANSFER_READ_BIT, TS_IMPOSTOR_MIPS)};
            gpu::pipelineBarrier(cmd, toCopy);
            VkBufferImageCopy regions[2] = {};
            for (int m = 0; m < 2; ++m) {
                const int32_t texel = int32_t((4 * TS_IMPOSTOR_CELL + TS_IMPOSTOR_CELL / 2) >> mips[m]);
                regions[m].bufferOffset = VkDeviceSize(m) * layers * 4;
                regions[m].imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, mips[m], 0, layers};
                regions[m].imageOffset = {texel, texel, 0};
                regions[m].imageExtent = {1, 1, 1};
            }
            vkCmdCopyImageToBuffer(cmd, image.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback.handle(), 2,
                                   regions);
        });
    ASSERT_EQ(bytes.size(), size_t(2) * layers * 4);

    auto texelAt = [&](int m, uint32_t layer) {
        uint8_t texel[4];
        std::memcpy(texel, bytes.data() + (size_t(m) * layers + layer) * 4, 4);
        return glm::u8vec4(texel[0], texel[1], texel[2], texel[3]);
    };
    for (int m = 0; m < 2; ++m)
        for (uint32_t clip = 0; clip < 6; ++clip)
            for (uint32_t phase = 0; phase < TS_IMPOSTOR_PHASES; ++phase) {
                glm::u8vec3 expected;
                if (clip < 3)
                    expected = syntheticImpostorColor(0, clip, phase);
                else if (clip == 3) // the rest pose shows the first clip
                    expected = syntheticImpostorColor(1, 0, phase);
                else
                    expected = syntheticImpostorColor(1, clip - 4, phase);
                const glm::u8vec4 texel = texelAt(m, firstLayers[clip] + phase);
                SCOPED_TRACE("mip " + std::to_string(mips[m]) + ", clip " + std::to_string(clip) + ", phase " +
                             std::to_string(phase));
                EXPECT_EQ(texel.r, expected.r);
                EXPECT_EQ(texel.g, expected.g);
                EXPECT_EQ(texel.b, expected.b);
                EXPECT_GT(texel.a, 0);
            }
    EXPECT_EQ(GpuTestDevice::validationMessages(), messagesBefore);
}
