// The crowd's impostor atlases on the GPU (GpuImpostorAtlas) as the cards
// sample them: layer ids.z * TS_IMPOSTOR_PHASES + k holds phase k of global
// baked clip ids.z, for every creature of a crowd and at every mip level,
// whichever layout its atlas has (a clip per baked clip, or its asset's
// clips only, the rest pose not baked, as character::bakeImpostors makes
// it), and is clear where a creature has none; under the validation layer.
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

    const uint32_t layers = uint32_t(baked.clips.size()) * TS_IMPOSTOR_PHASES;
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

    for (int m = 0; m < 2; ++m)
        for (uint32_t layer = 0; layer < layers; ++layer) {
            const uint32_t clip = layer / TS_IMPOSTOR_PHASES, phase = layer % TS_IMPOSTOR_PHASES;
            glm::u8vec3 expected(0);
            if (clip < 3)
                expected = syntheticImpostorColor(0, clip, phase);
            else if (clip == 3) // the rest pose shows the first clip's first phase
                expected = syntheticImpostorColor(1, 0, 0);
            else if (clip < 6)
                expected = syntheticImpostorColor(1, clip - 4, phase);
            uint8_t texel[4];
            std::memcpy(texel, bytes.data() + (size_t(m) * layers + layer) * 4, 4);
            SCOPED_TRACE("mip " + std::to_string(mips[m]) + ", layer " + std::to_string(layer));
            EXPECT_EQ(texel[0], expected.r);
            EXPECT_EQ(texel[1], expected.g);
            EXPECT_EQ(texel[2], expected.b);
            EXPECT_EQ(texel[3] > 0, clip < 6) << "coverage " << int(texel[3]);
        }
    EXPECT_EQ(GpuTestDevice::validationMessages(), messagesBefore);
}
