#include "StreamoutCrowdResources.h"

#include "tessera/gpu/Barriers.h"
#include "tessera/gpu/VulkanCheck.h"

#include <algorithm>
#include <cstddef>
#include <vector>

namespace tessera::backends {

namespace {

/// State targets are this many texels wide (ids row-major): within every
/// device's maxImageDimension2D (4096 at least) with room for 4M ids.
constexpr uint32_t kStateWidth = 1024;

} // namespace

Result<std::unique_ptr<StreamoutCrowdResources>> StreamoutCrowdResources::create(gpu::Device& device, GpuCrowd& crowd) {
    const uint32_t width = std::clamp(crowd.maxIds(), 1u, kStateWidth);
    const uint32_t height = (crowd.maxIds() + width - 1) / width;
    const uint32_t limit = device.properties().limits.maxImageDimension2D;
    if (height > limit)
        return Error{"createCrowd: streamout keeps the LOD state of " + std::to_string(crowd.maxIds()) + " ids in a " +
                     std::to_string(width) + " x " + std::to_string(height) +
                     " render target, more than this device's maxImageDimension2D (" + std::to_string(limit) + ")"};

    std::unique_ptr<StreamoutCrowdResources> r(new StreamoutCrowdResources());
    // Every id starts out of view: its first frame in view takes its tier at
    // once, without a fade.
    const std::vector<uint32_t> none(size_t(width) * height, shader::tsLodStateNone());
    for (uint32_t i = 0; i < 2; ++i) {
        gpu::ImageDesc desc;
        desc.width = width;
        desc.height = height;
        desc.format = VK_FORMAT_R32_UINT;
        desc.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
        desc.name = "streamout.crowd.lodState[" + std::to_string(i) + "]";
        r->mState[i] = gpu::Image(device, desc);
        r->mState[i].upload(std::as_bytes(std::span<const uint32_t>(none)), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    }

    const VkBufferUsageFlags xfb = VK_BUFFER_USAGE_TRANSFORM_FEEDBACK_BUFFER_BIT_EXT;
    const VkDeviceSize survivorBytes = VkDeviceSize(crowd.maxInstances()) * kSurvivorBytes;
    r->mSurvivors = gpu::Buffer(device, survivorBytes, xfb | VK_BUFFER_USAGE_VERTEX_BUFFER_BIT,
                                gpu::MemoryUsage::GpuOnly, "streamout.crowd.survivors");
    r->mMeshSurvivors = gpu::Buffer(device, survivorBytes, xfb | VK_BUFFER_USAGE_VERTEX_BUFFER_BIT,
                                    gpu::MemoryUsage::GpuOnly, "streamout.crowd.meshSurvivors");

    const uint32_t creatures = uint32_t(crowd.creatures().size());
    r->mCreatures = creatures;
    r->mQueryCount = (TS_LOD_TIERS + 2) * creatures;
    VkQueryPoolCreateInfo pool{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    pool.queryType = VK_QUERY_TYPE_TRANSFORM_FEEDBACK_STREAM_EXT;
    pool.queryCount = r->mQueryCount;
    VkQueryPool queries = VK_NULL_HANDLE;
    TESSERA_VK_CHECK(vkCreateQueryPool(device.handle(), &pool, nullptr, &queries));
    r->mQueries = {device, queries, "streamout.crowd.listQueries"};
    r->mCounts = gpu::Buffer(device, r->mQueryCount * kResultBytes,
                             VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                             gpu::MemoryUsage::GpuOnly, "streamout.crowd.listCounts");

    // Per creature: {survivors, 1, 0, 0}, {near entries, 1, 0, 0},
    // {nearStride, near entries, 0, 0} and {mesh survivors, 1, 0, 0}; the
    // counts are copied in every frame.
    std::vector<VkDrawIndirectCommand> draws(4 * creatures, VkDrawIndirectCommand{0, 1, 0, 0});
    for (uint32_t c = 0; c < creatures; ++c) draws[2 * creatures + c] = {crowd.nearStride(), 0, 0, 0};
    r->mDraws = gpu::Buffer(device, draws.size() * sizeof(VkDrawIndirectCommand), VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT,
                            gpu::MemoryUsage::GpuOnly, "streamout.crowd.draws");
    r->mDraws.upload(std::span<const VkDrawIndirectCommand>(draws));

    std::vector<shader::CharacterVertex> cages;
    for (const GpuCrowd::Creature& c : crowd.creatures()) {
        r->mCageBase.push_back(uint32_t(cages.size()));
        const auto& vertices = c.character->gpuVertices();
        cages.insert(cages.end(), vertices.begin(), vertices.end());
    }
    const VkDeviceSize cageBytes = cages.size() * sizeof(shader::CharacterVertex);
    const uint64_t cageTexels = cageBytes / 16;
    if (cageTexels > device.properties().limits.maxTexelBufferElements)
        return Error{"createCrowd: streamout reads the cages as " + std::to_string(cageTexels) +
                     " texels, more than this device's maxTexelBufferElements (" +
                     std::to_string(device.properties().limits.maxTexelBufferElements) + ")"};
    r->mCages = gpu::Buffer(device, cageBytes, VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT, gpu::MemoryUsage::GpuOnly,
                            "streamout.crowd.cages");
    r->mCages.upload(std::span<const shader::CharacterVertex>(cages));
    r->mCagesView =
        gpu::BufferView(device, r->mCages, VK_FORMAT_R32G32B32A32_UINT, 0, cageBytes, "streamout.crowd.cages.texels");
    return r;
}

void StreamoutCrowdResources::copyResults(VkCommandBuffer cmd, uint32_t first, uint32_t count) {
    vkCmdCopyQueryPoolResults(cmd, mQueries.get(), first, count, mCounts.handle(), resultOffset(first), kResultBytes,
                              VK_QUERY_RESULT_WAIT_BIT);
    gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_COPY_BIT,
                       VK_ACCESS_2_TRANSFER_READ_BIT);
}

void StreamoutCrowdResources::countsToDraws(VkCommandBuffer cmd, uint32_t firstQuery,
                                            VkDeviceSize (StreamoutCrowdResources::*draw)(uint32_t) const) {
    copyResults(cmd, firstQuery, mCreatures);
    std::vector<VkBufferCopy> copies;
    for (uint32_t c = 0; c < mCreatures; ++c)
        copies.push_back({resultOffset(firstQuery + c), (this->*draw)(c) + offsetof(VkDrawIndirectCommand, vertexCount),
                          sizeof(uint32_t)});
    vkCmdCopyBuffer(cmd, mCounts.handle(), mDraws.handle(), uint32_t(copies.size()), copies.data());
    gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                       VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT, VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT);
}

uint64_t StreamoutCrowdResources::bytes() const {
    uint64_t total = mSurvivors.size() + mMeshSurvivors.size() + mCounts.size() + mDraws.size() + mCages.size();
    for (const gpu::Image& image : mState) total += uint64_t(image.width()) * image.height() * sizeof(uint32_t);
    return total;
}

} // namespace tessera::backends
