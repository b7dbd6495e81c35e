#include "R2vbCrowdTargets.h"

#include <algorithm>
#include <optional>
#include <string>
#include <utility>

namespace tessera::backends {
namespace {

/// The longest side a render target may have here: an image, a render area
/// and a viewport must all hold it. `name` is the limit that binds.
struct SideLimit {
    uint32_t texels = 0;
    std::string name;
};

SideLimit sideLimit(const VkPhysicalDeviceLimits& limits) {
    const std::pair<uint32_t, const char*> all[] = {{limits.maxImageDimension2D, "maxImageDimension2D"},
                                                    {limits.maxFramebufferWidth, "maxFramebufferWidth"},
                                                    {limits.maxFramebufferHeight, "maxFramebufferHeight"},
                                                    {limits.maxViewportDimensions[0], "maxViewportDimensions"},
                                                    {limits.maxViewportDimensions[1], "maxViewportDimensions"}};
    SideLimit best{all[0].first, all[0].second};
    for (const auto& [texels, name] : all)
        if (texels < best.texels) best = {texels, name};
    return best;
}

/// A row-major target for `regions` regions of `texels` texels each, every
/// region in whole rows: R2VB_CROWD_WIDTH wide (narrower for a small one),
/// widened until its rows fit `limit`; none when even `limit` texels a row
/// are too few.
struct Shape {
    uint32_t width = 1, regionRows = 1, rows = 1;
};

std::optional<Shape> shapeFor(uint64_t texels, uint32_t regions, uint32_t limit) {
    uint64_t width = std::min<uint64_t>(std::clamp<uint64_t>(texels, 1, R2VB_CROWD_WIDTH), limit);
    for (;;) {
        const uint64_t regionRows = std::max<uint64_t>((texels + width - 1) / width, 1);
        if (regionRows * regions <= limit && width <= limit)
            return Shape{uint32_t(width), uint32_t(regionRows), uint32_t(regionRows * regions)};
        if (width >= limit) return std::nullopt;
        width = std::min<uint64_t>(width * 2, limit);
    }
}

} // namespace

Result<std::unique_ptr<R2vbCrowdTargets>> R2vbCrowdTargets::create(gpu::Device& device, const GpuCrowd& crowd,
                                                                   uint32_t id) {
    const SideLimit limit = sideLimit(device.properties().limits);
    auto tooLarge = [&](const std::string& what) {
        return fail("createCrowd: ", what, " would not fit in render targets of at most ", std::to_string(limit.texels),
                    " texels a side, the most ", device.features().deviceName, " allows (", limit.name, ")");
    };
    const uint32_t creatures = uint32_t(crowd.creatures().size());
    const uint32_t lists = TS_LOD_TIERS * creatures;
    const uint64_t nearCommandTexels = uint64_t(creatures) * crowd.nearSlots() * TS_CROWD_NEAR_COMMAND_WORDS / 4;
    const uint64_t cageTexels = uint64_t(crowd.nearSlots()) * crowd.nearStride();
    const auto state = shapeFor(crowd.maxIds(), 1, limit.texels);
    if (!state) return tooLarge("the LOD state of " + std::to_string(crowd.maxIds()) + " instance ids");
    const auto entries = shapeFor(crowd.maxInstances(), lists, limit.texels);
    if (!entries)
        return tooLarge("the tier lists (" + std::to_string(lists) + " lists of " +
                        std::to_string(crowd.maxInstances()) + " entries)");
    const auto slots = shapeFor(crowd.nearSlots(), 1, limit.texels);
    const auto commands = shapeFor(nearCommandTexels, 1, limit.texels);
    if (!slots || !commands)
        return tooLarge("the near tier's commands (" + std::to_string(crowd.nearSlots()) + " slots x " +
                        std::to_string(creatures) + " creatures)");
    const auto cages = shapeFor(cageTexels, 1, limit.texels);
    if (!cages)
        return tooLarge("the near tier's compressed cages (" + std::to_string(crowd.nearSlots()) + " slots x " +
                        std::to_string(crowd.nearStride()) + " vertices)");

    std::unique_ptr<R2vbCrowdTargets> t(new R2vbCrowdTargets());
    // The pyramid's base: the smallest power-of-two square holding every instance.
    while (uint64_t(t->mSide) * t->mSide < crowd.maxInstances()) {
        t->mSide *= 2;
        ++t->mTop;
    }
    const shader::uvec2 even = shader::r2vbPyramidAtlasSize(0, t->mSide, t->mTop);
    const shader::uvec2 odd = shader::r2vbPyramidAtlasSize(1, t->mSide, t->mTop);
    if (even.x > limit.texels)
        return tooLarge("the histogram pyramid of " + std::to_string(crowd.maxInstances()) + " instances (a " +
                        std::to_string(even.x) + " x " + std::to_string(even.y) + " atlas)");

    const std::string prefix = "r2vb.crowd" + std::to_string(id) + ".";
    auto target = [&](uint32_t width, uint32_t height, VkFormat format, VkDeviceSize texelBytes,
                      VkImageUsageFlags usage, const char* name) {
        gpu::ImageDesc desc;
        desc.width = width;
        desc.height = height;
        desc.format = format;
        desc.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | usage;
        desc.name = prefix + name;
        t->mBytes += VkDeviceSize(width) * height * texelBytes;
        return gpu::Image(device, desc);
    };
    auto buffer = [&](VkDeviceSize size, const char* name) {
        t->mBytes += size;
        return gpu::Buffer(device, size, VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT,
                           gpu::MemoryUsage::GpuOnly, prefix + name);
    };
    const VkImageUsageFlags sampled = VK_IMAGE_USAGE_SAMPLED_BIT;
    const VkImageUsageFlags copied = VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    const VkFormat uint4 = VK_FORMAT_R32G32B32A32_UINT;
    t->mState[0] = target(state->width, state->rows, VK_FORMAT_R32_UINT, 4, sampled, "state0");
    t->mState[1] = target(state->width, state->rows, VK_FORMAT_R32_UINT, 4, sampled, "state1");
    t->mPyramid[0] = target(even.x, even.y, uint4, 16, sampled, "pyramidEven");
    t->mPyramid[1] = target(odd.x, odd.y, uint4, 16, sampled, "pyramidOdd");
    t->mLists = lists;
    t->mListDraws = target(lists, 1, uint4, 16, copied, "listDraws");
    t->mListCounts = target(lists, 1, VK_FORMAT_R32_UINT, 4, copied, "listCounts");
    t->mListDrawBuffer = buffer(VkDeviceSize(lists) * sizeof(VkDrawIndirectCommand), "listDrawBuffer");
    t->mEntries = target(entries->width, entries->rows, uint4, 16, copied, "entries");
    t->mRegionTexels = entries->width * entries->regionRows;
    t->mSlotRecords = target(slots->width, slots->rows, uint4, 16, copied, "slotRecords");
    t->mSlotSkinDraws = target(slots->width, slots->rows, uint4, 16, copied, "slotSkinDraws");
    t->mSkinDrawBuffer = buffer(VkDeviceSize(crowd.nearSlots()) * sizeof(VkDrawIndirectCommand), "skinDrawBuffer");
    t->mNearCommands = target(commands->width, commands->rows, uint4, 16, copied, "nearCommands");
    t->mNearCages = target(cages->width, cages->rows, uint4, 16, copied, "nearCages");
    return t;
}

} // namespace tessera::backends
