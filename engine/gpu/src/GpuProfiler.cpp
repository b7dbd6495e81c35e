#include "tessera/gpu/GpuProfiler.h"

#include "tessera/gpu/Device.h"
#include "tessera/gpu/VulkanCheck.h"
#include "tessera/core/Log.h"
#include "tessera/profiler/Profiler.h"

#include <algorithm>
#include <cassert>

namespace tessera::gpu {
namespace {

// Results come back in the order of the flag bits, so this table maps each
// bit to the PipelineStatistics field it fills.
struct StatisticField {
    VkQueryPipelineStatisticFlagBits bit;
    uint64_t profiler::PipelineStatistics::*field;
    bool needsGeometry;
    bool needsTessellation;
};

constexpr StatisticField kFields[] = {
    {VK_QUERY_PIPELINE_STATISTIC_INPUT_ASSEMBLY_VERTICES_BIT, &profiler::PipelineStatistics::inputAssemblyVertices, false, false},
    {VK_QUERY_PIPELINE_STATISTIC_INPUT_ASSEMBLY_PRIMITIVES_BIT, &profiler::PipelineStatistics::inputAssemblyPrimitives, false, false},
    {VK_QUERY_PIPELINE_STATISTIC_VERTEX_SHADER_INVOCATIONS_BIT, &profiler::PipelineStatistics::vertexShaderInvocations, false, false},
    {VK_QUERY_PIPELINE_STATISTIC_GEOMETRY_SHADER_INVOCATIONS_BIT, &profiler::PipelineStatistics::geometryShaderInvocations, true, false},
    {VK_QUERY_PIPELINE_STATISTIC_GEOMETRY_SHADER_PRIMITIVES_BIT, &profiler::PipelineStatistics::geometryShaderPrimitives, true, false},
    {VK_QUERY_PIPELINE_STATISTIC_CLIPPING_INVOCATIONS_BIT, &profiler::PipelineStatistics::clippingInvocations, false, false},
    {VK_QUERY_PIPELINE_STATISTIC_CLIPPING_PRIMITIVES_BIT, &profiler::PipelineStatistics::clippingPrimitives, false, false},
    {VK_QUERY_PIPELINE_STATISTIC_FRAGMENT_SHADER_INVOCATIONS_BIT, &profiler::PipelineStatistics::fragmentShaderInvocations, false, false},
    {VK_QUERY_PIPELINE_STATISTIC_TESSELLATION_CONTROL_SHADER_PATCHES_BIT, &profiler::PipelineStatistics::tessControlPatches, false, true},
    {VK_QUERY_PIPELINE_STATISTIC_TESSELLATION_EVALUATION_SHADER_INVOCATIONS_BIT, &profiler::PipelineStatistics::tessEvaluationInvocations, false, true},
    {VK_QUERY_PIPELINE_STATISTIC_COMPUTE_SHADER_INVOCATIONS_BIT, &profiler::PipelineStatistics::computeShaderInvocations, false, false},
};

// Task and mesh invocations, in their own pool: counting them slows NVIDIA's
// mesh stage about 7x (driver 580.159: 8.1 against 1.2 ms for the terrain's
// far continuous row on an H200), so they run on every kMeshCountInterval-th
// frame and when a benchmark asks, never on the frames it times.
constexpr VkQueryPipelineStatisticFlags kMeshStatisticFlags =
    VK_QUERY_PIPELINE_STATISTIC_TASK_SHADER_INVOCATIONS_BIT_EXT |
    VK_QUERY_PIPELINE_STATISTIC_MESH_SHADER_INVOCATIONS_BIT_EXT;
constexpr uint64_t kMeshCountInterval = 16;

} // namespace

GpuProfiler::GpuProfiler(Device& device, profiler::Profiler& profiler, uint32_t framesInFlight)
    : mDevice(device), mProfiler(profiler), mSlots(framesInFlight) {
    const auto& features = device.features();
    mTimestamps = features.timestamps;
    mStatistics = features.pipelineStatistics;
    mNsPerTick = device.properties().limits.timestampPeriod;

    if (mTimestamps) {
        VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
        info.queryType = VK_QUERY_TYPE_TIMESTAMP;
        info.queryCount = 2 * kMaxPassesPerFrame * framesInFlight;
        TESSERA_VK_CHECK(vkCreateQueryPool(device.handle(), &info, nullptr, &mTimestampPool));
        device.setName(VK_OBJECT_TYPE_QUERY_POOL, mTimestampPool, "profiler.timestamps");
    }
    if (mStatistics) {
        for (const auto& f : kFields) {
            if (f.needsGeometry && !features.geometryShader) continue;
            if (f.needsTessellation && !features.tessellationShader) continue;
            mStatisticFlags |= f.bit;
            ++mStatisticCount;
        }
        VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
        info.queryType = VK_QUERY_TYPE_PIPELINE_STATISTICS;
        info.queryCount = kMaxPassesPerFrame * framesInFlight;
        info.pipelineStatistics = mStatisticFlags;
        TESSERA_VK_CHECK(vkCreateQueryPool(device.handle(), &info, nullptr, &mStatisticsPool));
        device.setName(VK_OBJECT_TYPE_QUERY_POOL, mStatisticsPool, "profiler.pipelineStatistics");
    }
    if (mStatistics && features.meshShaderQueries) {
        VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
        info.queryType = VK_QUERY_TYPE_MESH_PRIMITIVES_GENERATED_EXT;
        info.queryCount = kMaxPassesPerFrame * framesInFlight;
        TESSERA_VK_CHECK(vkCreateQueryPool(device.handle(), &info, nullptr, &mMeshPrimitivesPool));
        device.setName(VK_OBJECT_TYPE_QUERY_POOL, mMeshPrimitivesPool, "profiler.meshPrimitives");
        // The same statistics and the two mesh counters: a frame that counts
        // them uses this pool instead (two statistics queries cannot both be
        // active), whose results have the mesh counters after the others.
        info.queryType = VK_QUERY_TYPE_PIPELINE_STATISTICS;
        info.pipelineStatistics = mStatisticFlags | kMeshStatisticFlags;
        TESSERA_VK_CHECK(vkCreateQueryPool(device.handle(), &info, nullptr, &mMeshStatisticsPool));
        device.setName(VK_OBJECT_TYPE_QUERY_POOL, mMeshStatisticsPool, "profiler.pipelineStatisticsWithMesh");
    }
}

GpuProfiler::~GpuProfiler() {
    if (mTimestampPool) {
        mDevice.clearName(VK_OBJECT_TYPE_QUERY_POOL, mTimestampPool);
        vkDestroyQueryPool(mDevice.handle(), mTimestampPool, nullptr);
    }
    if (mStatisticsPool) {
        mDevice.clearName(VK_OBJECT_TYPE_QUERY_POOL, mStatisticsPool);
        vkDestroyQueryPool(mDevice.handle(), mStatisticsPool, nullptr);
    }
    for (VkQueryPool pool : {mMeshPrimitivesPool, mMeshStatisticsPool})
        if (pool) {
            mDevice.clearName(VK_OBJECT_TYPE_QUERY_POOL, pool);
            vkDestroyQueryPool(mDevice.handle(), pool, nullptr);
        }
}

void GpuProfiler::beginFrame(VkCommandBuffer cmd, uint32_t slot, uint64_t frameIndex) {
    mRecordingSlot = slot;
    Slot& s = mSlots[slot];
    s.frameIndex = frameIndex;
    s.passes.clear();
    s.pending = false;
    if (mTimestampPool) vkCmdResetQueryPool(cmd, mTimestampPool, 2 * kMaxPassesPerFrame * slot, 2 * kMaxPassesPerFrame);
    if (mStatisticsPool) vkCmdResetQueryPool(cmd, mStatisticsPool, kMaxPassesPerFrame * slot, kMaxPassesPerFrame);
    if (mMeshPrimitivesPool)
        vkCmdResetQueryPool(cmd, mMeshPrimitivesPool, kMaxPassesPerFrame * slot, kMaxPassesPerFrame);
    // Take the request on every frame, so one made while counting is off
    // (no mesh queries on the device) does not wait for a later profiler.
    const bool requested = mProfiler.takeMeshInvocationRequest();
    s.countsMeshInvocations = mMeshStatisticsPool && (requested || frameIndex % kMeshCountInterval == 0);
    if (s.countsMeshInvocations)
        vkCmdResetQueryPool(cmd, mMeshStatisticsPool, kMaxPassesPerFrame * slot, kMaxPassesPerFrame);
}

void GpuProfiler::beginPass(VkCommandBuffer cmd, const char* name) {
    assert(!mInPass && "GPU passes do not nest");
    Slot& s = mSlots[mRecordingSlot];
    mInPass = true;
    const float color[4] = {0.3f, 0.6f, 0.9f, 1.0f};
    mDevice.beginLabel(cmd, name, color);
    mInTimedPass = s.passes.size() < kMaxPassesPerFrame;
    if (!mInTimedPass) {
        if (!mWarnedUntimed)
            log::warning("more than " + std::to_string(kMaxPassesPerFrame) +
                         " GPU passes in a frame: the rest are labelled but not timed");
        mWarnedUntimed = true;
        return;
    }
    const uint32_t pass = static_cast<uint32_t>(s.passes.size());
    s.passes.push_back({name});
    if (mTimestampPool)
        vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_TOP_OF_PIPE_BIT, mTimestampPool,
                             2 * (kMaxPassesPerFrame * mRecordingSlot + pass));
    if (mStatisticsPool)
        vkCmdBeginQuery(cmd, statisticsPool(s), kMaxPassesPerFrame * mRecordingSlot + pass, 0);
    if (mMeshPrimitivesPool) vkCmdBeginQuery(cmd, mMeshPrimitivesPool, kMaxPassesPerFrame * mRecordingSlot + pass, 0);
}

void GpuProfiler::endPass(VkCommandBuffer cmd) {
    assert(mInPass);
    mInPass = false;
    if (!mInTimedPass) {
        mDevice.endLabel(cmd);
        return;
    }
    Slot& s = mSlots[mRecordingSlot];
    const uint32_t pass = static_cast<uint32_t>(s.passes.size() - 1);
    if (mStatisticsPool) vkCmdEndQuery(cmd, statisticsPool(s), kMaxPassesPerFrame * mRecordingSlot + pass);
    if (mMeshPrimitivesPool) vkCmdEndQuery(cmd, mMeshPrimitivesPool, kMaxPassesPerFrame * mRecordingSlot + pass);
    if (mTimestampPool)
        vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_BOTTOM_OF_PIPE_BIT, mTimestampPool,
                             2 * (kMaxPassesPerFrame * mRecordingSlot + pass) + 1);
    mDevice.endLabel(cmd);
}

void GpuProfiler::markSubmitted(uint32_t slot, uint64_t cpuNs) {
    mSlots[slot].submitNs = cpuNs;
    mSlots[slot].pending = true;
}

void GpuProfiler::collect(uint32_t slot) {
    Slot& s = mSlots[slot];
    if (!s.pending || s.passes.empty()) return;
    s.pending = false;
    const uint32_t count = static_cast<uint32_t>(s.passes.size());

    std::vector<uint64_t> stamps(2 * count, 0);
    if (mTimestampPool)
        TESSERA_VK_CHECK(vkGetQueryPoolResults(mDevice.handle(), mTimestampPool, 2 * kMaxPassesPerFrame * slot, 2 * count,
                                               stamps.size() * sizeof(uint64_t), stamps.data(), sizeof(uint64_t),
                                               VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
    // Per pass: the statistics in the order of their bits, then task and
    // mesh invocations on a frame that counts them.
    const uint32_t perPass = mStatisticCount + (s.countsMeshInvocations ? 2 : 0);
    std::vector<uint64_t> stats(static_cast<size_t>(count) * perPass, 0);
    if (mStatisticsPool)
        TESSERA_VK_CHECK(vkGetQueryPoolResults(mDevice.handle(), statisticsPool(s), kMaxPassesPerFrame * slot, count,
                                               stats.size() * sizeof(uint64_t), stats.data(),
                                               perPass * sizeof(uint64_t),
                                               VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
    std::vector<uint64_t> meshPrimitives(mMeshPrimitivesPool ? count : 0, 0);
    if (mMeshPrimitivesPool)
        TESSERA_VK_CHECK(vkGetQueryPoolResults(mDevice.handle(), mMeshPrimitivesPool, kMaxPassesPerFrame * slot, count,
                                               meshPrimitives.size() * sizeof(uint64_t), meshPrimitives.data(),
                                               sizeof(uint64_t), VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));

    // GPU ticks have their own epoch. The first frame's first timestamp is
    // anchored at its CPU submission time, and every later frame reuses that
    // offset: one monotonic GPU clock keeps frames in flight from overlapping
    // on the GPU track, which per-frame anchoring would make them do.
    if (!mHaveEpoch && !stamps.empty()) {
        mGpuEpochTicks = stamps[0];
        mGpuEpochCpuNs = s.submitNs;
        mHaveEpoch = true;
    }
    for (uint32_t p = 0; p < count; ++p) {
        profiler::GpuPassEvent event;
        event.name = s.passes[p].name;
        event.frame = s.frameIndex;
        if (mTimestampPool) {
            const double begin = static_cast<double>(int64_t(stamps[2 * p] - mGpuEpochTicks)) * mNsPerTick;
            const double end = static_cast<double>(int64_t(stamps[2 * p + 1] - mGpuEpochTicks)) * mNsPerTick;
            event.startNs = uint64_t(std::max(0.0, double(mGpuEpochCpuNs) + begin));
            event.durationNs = end > begin ? static_cast<uint64_t>(end - begin) : 0;
        } else {
            event.startNs = s.submitNs;
        }
        if (mStatisticsPool) {
            profiler::PipelineStatistics ps;
            const uint64_t* values = &stats[static_cast<size_t>(p) * perPass];
            uint32_t i = 0;
            for (const auto& f : kFields)
                if (mStatisticFlags & f.bit) ps.*(f.field) = values[i++];
            if (mMeshPrimitivesPool) ps.meshPrimitivesGenerated = meshPrimitives[p];
            if (s.countsMeshInvocations) {
                ps.taskShaderInvocations = values[mStatisticCount];
                ps.meshShaderInvocations = values[mStatisticCount + 1];
            }
            event.stats = ps;
        }
        mProfiler.recordGpuPass(std::move(event));
    }
}

} // namespace tessera::gpu
