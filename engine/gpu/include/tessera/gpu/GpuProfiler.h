#pragma once
/// @file GpuProfiler.h
/// Timestamp and pipeline-statistics queries around every pass, resolved into
/// the engine Profiler once the frame's fence has signalled (never stalling).

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <vector>

namespace tessera::profiler {
class Profiler;
}

namespace tessera::gpu {

class Device;

class GpuProfiler {
public:
    /// Passes a frame can time; later ones keep their debug label but get no
    /// queries (a warning says so once), never writing past the frame's
    /// queries: a dozen subdivision surfaces on r2vb take 5 passes each.
    static constexpr uint32_t kMaxPassesPerFrame = 256;

    GpuProfiler(Device& device, profiler::Profiler& profiler, uint32_t framesInFlight);
    ~GpuProfiler();
    GpuProfiler(const GpuProfiler&) = delete;
    GpuProfiler& operator=(const GpuProfiler&) = delete;

    /// Resets the slot's queries at the start of its command buffer.
    void beginFrame(VkCommandBuffer cmd, uint32_t slot, uint64_t frameIndex);
    /// Opens a pass: a debug label, a timestamp and, where the device has
    /// them, pipeline statistics. Passes do not nest (Vulkan forbids two
    /// active statistics queries); use Device::beginLabel inside a pass.
    void beginPass(VkCommandBuffer cmd, const char* name);
    void endPass(VkCommandBuffer cmd);
    /// Notes the CPU time of submission, used to place GPU events on the
    /// profiler's timeline.
    void markSubmitted(uint32_t slot, uint64_t cpuNs);
    /// Reads the slot's finished queries and records one GpuPassEvent per pass.
    void collect(uint32_t slot);

    bool timestampsSupported() const { return mTimestamps; }
    bool statisticsSupported() const { return mStatistics; }

private:
    struct Pass {
        std::string name;
    };
    struct Slot {
        uint64_t frameIndex = 0;
        uint64_t submitNs = 0;
        std::vector<Pass> passes; ///< the timed ones
        bool pending = false;
        bool countsMeshInvocations = false; ///< mMeshStatisticsPool's queries ran
    };

    bool mInTimedPass = false;
    bool mWarnedUntimed = false;
    Device& mDevice;
    profiler::Profiler& mProfiler;
    VkQueryPool mTimestampPool = VK_NULL_HANDLE;
    VkQueryPool mStatisticsPool = VK_NULL_HANDLE;
    /// VK_QUERY_TYPE_MESH_PRIMITIVES_GENERATED_EXT, where the device has it.
    VkQueryPool mMeshPrimitivesPool = VK_NULL_HANDLE;
    /// mStatisticsPool's statistics plus task and mesh shader invocations,
    /// used instead of it on the frames that count those
    /// (Profiler::requestMeshInvocationCount).
    VkQueryPool mMeshStatisticsPool = VK_NULL_HANDLE;
    VkQueryPool statisticsPool(const Slot& s) const {
        return s.countsMeshInvocations ? mMeshStatisticsPool : mStatisticsPool;
    }
    VkQueryPipelineStatisticFlags mStatisticFlags = 0;
    uint32_t mStatisticCount = 0;
    bool mTimestamps = false;
    bool mStatistics = false;
    double mNsPerTick = 1.0;
    uint64_t mGpuEpochTicks = 0;
    uint64_t mGpuEpochCpuNs = 0;
    bool mHaveEpoch = false;
    std::vector<Slot> mSlots;
    uint32_t mRecordingSlot = 0;
    bool mInPass = false;
};

} // namespace tessera::gpu
