#include "TessellationCapture.h"
#include "tessera/gpu/Barriers.h"

#include "tessera/gpu/VulkanCheck.h"

#include "tess_capture.tesc.spv.h"
#include "tess_capture.tese_quad_equal.spv.h"
#include "tess_capture.tese_quad_even.spv.h"
#include "tess_capture.tese_quad_odd.spv.h"
#include "tess_capture.tese_tri_equal.spv.h"
#include "tess_capture.tese_tri_even.spv.h"
#include "tess_capture.tese_tri_odd.spv.h"
#include "tess_capture.vert.spv.h"

#include <cstring>
#include <span>

namespace tessera::test {

namespace {

// Room for the largest patch: a quad at level 64 emits 2 * 64 * 64 triangles.
constexpr VkDeviceSize kCaptureBytes = 2 * 64 * 64 * 3 * sizeof(glm::vec4) * 2;

VkQueryPool createPool(gpu::Device& device, VkQueryType type, VkQueryPipelineStatisticFlags stats, const char* name) {
    VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    info.queryType = type;
    info.queryCount = 1;
    info.pipelineStatistics = stats;
    VkQueryPool pool = VK_NULL_HANDLE;
    TESSERA_VK_CHECK(vkCreateQueryPool(device.handle(), &info, nullptr, &pool));
    device.setName(VK_OBJECT_TYPE_QUERY_POOL, pool, name);
    return pool;
}

} // namespace

TessellationCapture::TessellationCapture(gpu::Device& device) : mDevice(device) {
    mLayout = gpu::PipelineLayout(device, {}, sizeof(glm::vec4) * 2, VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT,
                                  "tessCapture.layout");
    const std::span<const uint32_t> evaluation[6] = {tess_capture_tese_tri_equal_spv, tess_capture_tese_tri_odd_spv,
                                                     tess_capture_tese_tri_even_spv,  tess_capture_tese_quad_equal_spv,
                                                     tess_capture_tese_quad_odd_spv,  tess_capture_tese_quad_even_spv};
    for (size_t i = 0; i < mPipelines.size(); ++i) {
        gpu::GraphicsPipelineDesc desc;
        desc.name = "tessCapture.pipeline" + std::to_string(i);
        desc.layout = &mLayout;
        desc.stages = {{VK_SHADER_STAGE_VERTEX_BIT, tess_capture_vert_spv},
                       {VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT, tess_capture_tesc_spv},
                       {VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT, evaluation[i]}};
        desc.topology = VK_PRIMITIVE_TOPOLOGY_PATCH_LIST;
        desc.patchControlPoints = 1;
        desc.cullMode = VK_CULL_MODE_NONE;
        desc.depthTest = false;
        desc.depthWrite = false;
        desc.rasterizerDiscard = true;
        mPipelines[i] = gpu::Pipeline(device, desc);
    }
    mCapture = gpu::Buffer(device, kCaptureBytes, VK_BUFFER_USAGE_TRANSFORM_FEEDBACK_BUFFER_BIT_EXT,
                           gpu::MemoryUsage::GpuToCpu, "tessCapture.vertices");
    mCounter = gpu::Buffer(device, 16, VK_BUFFER_USAGE_TRANSFORM_FEEDBACK_COUNTER_BUFFER_BIT_EXT,
                           gpu::MemoryUsage::GpuToCpu, "tessCapture.counter");
    mStreamQueries = createPool(device, VK_QUERY_TYPE_TRANSFORM_FEEDBACK_STREAM_EXT, 0, "tessCapture.streamQuery");
    mStatsQueries = createPool(device, VK_QUERY_TYPE_PIPELINE_STATISTICS,
                               VK_QUERY_PIPELINE_STATISTIC_TESSELLATION_EVALUATION_SHADER_INVOCATIONS_BIT,
                               "tessCapture.statsQuery");
}

TessellationCapture::~TessellationCapture() {
    mDevice.waitIdle();
    vkDestroyQueryPool(mDevice.handle(), mStreamQueries, nullptr);
    vkDestroyQueryPool(mDevice.handle(), mStatsQueries, nullptr);
}

Result<TessellationCaptureResult> TessellationCapture::run(CaptureDomain domain, CaptureSpacing spacing,
                                                           const std::array<float, 4>& outer,
                                                           const std::array<float, 2>& inner) {
    const auto& fn = mDevice.fn();
    const gpu::Pipeline& pipeline = mPipelines[size_t(domain) * 3 + size_t(spacing)];
    const glm::vec4 levels[2] = {{outer[0], outer[1], outer[2], outer[3]}, {inner[0], inner[1], 0.0f, 0.0f}};
    std::memset(mCounter.mapped(), 0, 16);
    mDevice.submitImmediate(
        [&](VkCommandBuffer cmd) {
            vkCmdResetQueryPool(cmd, mStreamQueries, 0, 1);
            vkCmdResetQueryPool(cmd, mStatsQueries, 0, 1);
            // Transform feedback only exists inside rendering; nothing is
            // rasterised (rasterizer discard), so no attachments are needed.
            VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
            rendering.renderArea = {{0, 0}, {1, 1}};
            rendering.layerCount = 1;
            vkCmdBeginRendering(cmd, &rendering);
            const VkViewport viewport{0.0f, 0.0f, 1.0f, 1.0f, 0.0f, 1.0f};
            vkCmdSetViewport(cmd, 0, 1, &viewport);
            vkCmdSetScissor(cmd, 0, 1, &rendering.renderArea);
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline.handle());
            vkCmdPushConstants(cmd, mLayout.handle(), VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT, 0, sizeof levels, levels);
            const VkBuffer buffer = mCapture.handle();
            const VkDeviceSize zero = 0, size = kCaptureBytes;
            fn.cmdBindTransformFeedbackBuffers(cmd, 0, 1, &buffer, &zero, &size);
            vkCmdBeginQuery(cmd, mStatsQueries, 0, 0);
            vkCmdBeginQuery(cmd, mStreamQueries, 0, 0);
            fn.cmdBeginTransformFeedback(cmd, 0, 0, nullptr, nullptr);
            vkCmdDraw(cmd, 1, 1, 0, 0);
            const VkBuffer counter = mCounter.handle();
            fn.cmdEndTransformFeedback(cmd, 0, 1, &counter, &zero);
            vkCmdEndQuery(cmd, mStreamQueries, 0);
            vkCmdEndQuery(cmd, mStatsQueries, 0);
            vkCmdEndRendering(cmd);
            tessera::gpu::memoryBarrier(
                cmd, VK_PIPELINE_STAGE_2_TRANSFORM_FEEDBACK_BIT_EXT,
                VK_ACCESS_2_TRANSFORM_FEEDBACK_WRITE_BIT_EXT | VK_ACCESS_2_TRANSFORM_FEEDBACK_COUNTER_WRITE_BIT_EXT,
                VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
        },
        "tessCapture");

    TessellationCaptureResult result;
    uint64_t stream[2] = {};
    if (vkGetQueryPoolResults(mDevice.handle(), mStreamQueries, 0, 1, sizeof stream, stream, sizeof stream,
                              VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT) != VK_SUCCESS)
        return fail("transform-feedback query failed");
    uint64_t invocations = 0;
    if (vkGetQueryPoolResults(mDevice.handle(), mStatsQueries, 0, 1, sizeof invocations, &invocations,
                              sizeof invocations, VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT) != VK_SUCCESS)
        return fail("pipeline-statistics query failed");
    if (stream[0] != stream[1]) return fail("the capture buffer was too small for the patch");
    result.primitivesWritten = stream[0];
    result.evaluationInvocations = invocations;
    uint32_t bytes = 0;
    std::memcpy(&bytes, mCounter.mapped(), sizeof bytes);
    const auto* vertices = static_cast<const glm::vec4*>(mCapture.mapped());
    for (uint32_t i = 0; i < bytes / sizeof(glm::vec4); ++i) result.vertices.emplace_back(vertices[i]);
    return result;
}

} // namespace tessera::test
