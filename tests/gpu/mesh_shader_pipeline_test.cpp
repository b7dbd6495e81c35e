// The mesh-shader path through the shared Vulkan layer, on a device that has
// VK_EXT_mesh_shader (lavapipe 25 from bookworm-backports, any recent GPU):
// Debian's glslang compiles task and mesh stages, gpu::Pipeline builds them
// for dynamic rendering, DeviceFunctions draws them, and the extension's
// queries count them. A task stage keeps some of 128 tiles (as a backend's
// task stage keeps the patches in view) and launches one mesh workgroup per
// kept tile, which draws it as 32 triangles: the image must hold exactly the
// kept tiles, each in its own colour, and the queries must count exactly
// the kept tiles' primitives. Skipped, saying why, on a device without mesh
// shaders (Debian 12's lavapipe 22.3).
#include "GpuTestDevice.h"

#include "tessera/gpu/Barriers.h"
#include "tessera/gpu/Buffer.h"
#include "tessera/gpu/Image.h"
#include "tessera/gpu/Pipeline.h"
#include "tessera/gpu/PipelineLayout.h"
#include "tessera/gpu/Readback.h"
#include "tessera/gpu/RenderTarget.h"

#include "mesh_probe.frag.spv.h"
#include "mesh_probe.mesh.spv.h"
#include "mesh_probe.task.spv.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

using namespace tessera;
using namespace tessera::test;

namespace {

/// The shaders' push constants (mesh_probe.task reads the first three).
struct Probe {
    uint32_t tiles, tilesPerRow, dropEvery, width, height;
};

constexpr uint32_t kWidth = 128, kHeight = 64, kTile = 8;
constexpr uint32_t kTilesPerRow = kWidth / kTile, kTiles = kTilesPerRow * (kHeight / kTile);
constexpr uint32_t kDropEvery = 3;
constexpr uint32_t kTrianglesPerTile = 32;

/// Query pools this test owns for one draw (the profiler's are per frame).
struct Queries {
    VkDevice device = VK_NULL_HANDLE;
    VkQueryPool primitives = VK_NULL_HANDLE;
    VkQueryPool statistics = VK_NULL_HANDLE;
    ~Queries() {
        if (primitives) vkDestroyQueryPool(device, primitives, nullptr);
        if (statistics) vkDestroyQueryPool(device, statistics, nullptr);
    }
};

VkQueryPool makePool(gpu::Device& device, VkQueryType type, VkQueryPipelineStatisticFlags statistics,
                     const std::string& name) {
    VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    info.queryType = type;
    info.queryCount = 1;
    info.pipelineStatistics = statistics;
    VkQueryPool pool = VK_NULL_HANDLE;
    EXPECT_EQ(vkCreateQueryPool(device.handle(), &info, nullptr, &pool), VK_SUCCESS);
    device.setName(VK_OBJECT_TYPE_QUERY_POOL, pool, name);
    return pool;
}

} // namespace

TEST(MeshShaderPipeline, TaskStageAmplifiesAndTheQueriesCountWhatWasDrawn) {
    std::string why;
    gpu::Device* device = GpuTestDevice::get(why);
    if (!device) GTEST_SKIP() << why;
    const device::DeviceFeatures& features = device->features();
    if (!features.meshShader) GTEST_SKIP() << features.deviceName << " has no task and mesh shaders";
    ASSERT_GE(features.maxMeshOutputVertices, 25u);
    ASSERT_GE(features.maxMeshOutputPrimitives, kTrianglesPerTile);
    ASSERT_NE(device->fn().cmdDrawMeshTasks, nullptr);
    const uint64_t messagesBefore = GpuTestDevice::validationMessages();

    gpu::RenderTarget target(*device, kWidth, kHeight);
    const VkShaderStageFlags stages = VK_SHADER_STAGE_TASK_BIT_EXT | VK_SHADER_STAGE_MESH_BIT_EXT;
    gpu::PipelineLayout layout(*device, {}, sizeof(Probe), stages, "test.meshProbe.layout");
    gpu::GraphicsPipelineDesc desc;
    desc.name = "test.meshProbe";
    desc.layout = &layout;
    desc.stages = {{VK_SHADER_STAGE_TASK_BIT_EXT, mesh_probe_task_spv},
                   {VK_SHADER_STAGE_MESH_BIT_EXT, mesh_probe_mesh_spv},
                   {VK_SHADER_STAGE_FRAGMENT_BIT, mesh_probe_frag_spv}};
    desc.cullMode = VK_CULL_MODE_NONE;
    desc.depthTest = desc.depthWrite = false;
    desc.colorFormats = {gpu::RenderTarget::kColorFormat};
    desc.depthFormat = gpu::RenderTarget::kDepthFormat;
    gpu::Pipeline pipeline(*device, desc);

    Queries queries{device->handle()};
    // The mesh primitives query needs meshShaderQueries, as the statistics do.
    if (features.meshShaderQueries)
        queries.primitives =
            makePool(*device, VK_QUERY_TYPE_MESH_PRIMITIVES_GENERATED_EXT, 0, "test.meshProbe.primitivesQuery");
    const VkQueryPipelineStatisticFlags statistics = VK_QUERY_PIPELINE_STATISTIC_TASK_SHADER_INVOCATIONS_BIT_EXT |
                                                     VK_QUERY_PIPELINE_STATISTIC_MESH_SHADER_INVOCATIONS_BIT_EXT;
    if (features.meshShaderQueries)
        queries.statistics =
            makePool(*device, VK_QUERY_TYPE_PIPELINE_STATISTICS, statistics, "test.meshProbe.statisticsQuery");

    const Probe probe{kTiles, kTilesPerRow, kDropEvery, kWidth, kHeight};
    device->submitImmediate(
        [&](VkCommandBuffer cmd) {
            if (queries.primitives) vkCmdResetQueryPool(cmd, queries.primitives, 0, 1);
            if (queries.statistics) vkCmdResetQueryPool(cmd, queries.statistics, 0, 1);
            const float clear[4] = {0, 0, 0, 0};
            target.beginRendering(cmd, clear);
            const VkViewport viewport{0, 0, float(kWidth), float(kHeight), 0, 1};
            const VkRect2D scissor{{0, 0}, {kWidth, kHeight}};
            vkCmdSetViewport(cmd, 0, 1, &viewport);
            vkCmdSetScissor(cmd, 0, 1, &scissor);
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline.handle());
            vkCmdPushConstants(cmd, layout.handle(), stages, 0, sizeof probe, &probe);
            if (queries.primitives) vkCmdBeginQuery(cmd, queries.primitives, 0, 0);
            if (queries.statistics) vkCmdBeginQuery(cmd, queries.statistics, 0, 0);
            device->fn().cmdDrawMeshTasks(cmd, kTiles / 32, 1, 1);
            if (queries.statistics) vkCmdEndQuery(cmd, queries.statistics, 0);
            if (queries.primitives) vkCmdEndQuery(cmd, queries.primitives, 0);
            target.endRendering(cmd);
        },
        "test.meshProbe");

    const std::vector<std::byte> bytes = gpu::readBack(
        *device, VkDeviceSize(kWidth) * kHeight * 4, "test.meshProbe.readback", "test.meshProbe.read",
        [&](VkCommandBuffer cmd, const gpu::Buffer& readback) {
            gpu::Image& color = target.color();
            gpu::transitionImage(cmd, color.handle(), VK_IMAGE_ASPECT_COLOR_BIT,
                                 gpu::RenderTarget::kColorLayoutAfterPasses, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                                 VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                                 VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_COPY_BIT,
                                 VK_ACCESS_2_TRANSFER_READ_BIT);
            VkBufferImageCopy region{};
            region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
            region.imageExtent = {kWidth, kHeight, 1};
            vkCmdCopyImageToBuffer(cmd, color.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback.handle(), 1,
                                   &region);
        });
    ASSERT_EQ(bytes.size(), size_t(kWidth) * kHeight * 4);

    // Every pixel of a kept tile in the tile's colour, every other pixel clear.
    uint32_t kept = 0, wrongPixels = 0;
    for (uint32_t tile = 0; tile < kTiles; ++tile) {
        const bool keep = tile % kDropEvery != 0;
        kept += keep;
        const uint32_t x0 = (tile % kTilesPerRow) * kTile, y0 = (tile / kTilesPerRow) * kTile;
        const uint8_t expected[4] = {uint8_t(keep ? tile & 255u : 0), uint8_t(keep ? tile >> 8u : 0),
                                     uint8_t(keep ? 255 : 0), uint8_t(keep ? 255 : 0)};
        for (uint32_t y = y0; y < y0 + kTile; ++y)
            for (uint32_t x = x0; x < x0 + kTile; ++x)
                wrongPixels += std::memcmp(&bytes[(size_t(y) * kWidth + x) * 4], expected, 4) != 0;
    }
    EXPECT_EQ(wrongPixels, 0u) << "of " << kWidth * kHeight << " pixels";

    if (queries.primitives) {
        uint64_t primitives = 0;
        ASSERT_EQ(vkGetQueryPoolResults(device->handle(), queries.primitives, 0, 1, sizeof primitives, &primitives,
                                        sizeof primitives, VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
                  VK_SUCCESS);
        EXPECT_EQ(primitives, uint64_t(kept) * kTrianglesPerTile);
    }
    if (queries.statistics) {
        uint64_t invocations[2] = {};  // task, mesh: in the order of their bits
        ASSERT_EQ(vkGetQueryPoolResults(device->handle(), queries.statistics, 0, 1, sizeof invocations, invocations,
                                        sizeof invocations[0], VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
                  VK_SUCCESS);
        // Vulkan leaves whether a workgroup counts once or per invocation to
        // the implementation: at least one count per workgroup launched.
        EXPECT_GE(invocations[0], uint64_t(kTiles / 32));
        EXPECT_GE(invocations[1], uint64_t(kept));
        std::printf("task invocations %llu, mesh invocations %llu for %u task and %u mesh workgroups\n",
                    static_cast<unsigned long long>(invocations[0]), static_cast<unsigned long long>(invocations[1]),
                    kTiles / 32, kept);
    }
    EXPECT_EQ(GpuTestDevice::validationMessages(), messagesBefore);
}
