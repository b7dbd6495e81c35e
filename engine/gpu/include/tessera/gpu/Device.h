#pragma once
/// @file Device.h
/// The logical device every backend and the host share: one graphics queue,
/// debug names and labels, one-shot uploads, deferred deletion and a running
/// count of device memory (Granite's Device, pared down to what Tessera needs).

#include "tessera/device/DeviceFeatures.h"
#include "tessera/core/Result.h"
#include "tessera/gpu/Instance.h"
#include "tessera/gpu/UniqueHandle.h"

#include <vulkan/vulkan.h>

#include <atomic>
#include <functional>
#include <memory>
#include <string>
#include <type_traits>
#include <unordered_map>
#include <utility>
#include <vector>

namespace tessera::gpu {

/// Frames the CPU may record ahead of the GPU.
inline constexpr uint32_t kFramesInFlight = 2;

/// Extension entry points the layer loads once per device.
struct DeviceFunctions {
    PFN_vkCmdPushDescriptorSetKHR cmdPushDescriptorSet = nullptr;
    PFN_vkSetDebugUtilsObjectNameEXT setObjectName = nullptr;
    PFN_vkCmdBeginDebugUtilsLabelEXT cmdBeginLabel = nullptr;
    PFN_vkCmdEndDebugUtilsLabelEXT cmdEndLabel = nullptr;
    PFN_vkCmdInsertDebugUtilsLabelEXT cmdInsertLabel = nullptr;
    PFN_vkCmdBindTransformFeedbackBuffersEXT cmdBindTransformFeedbackBuffers = nullptr;
    PFN_vkCmdBeginTransformFeedbackEXT cmdBeginTransformFeedback = nullptr;
    PFN_vkCmdEndTransformFeedbackEXT cmdEndTransformFeedback = nullptr;
    PFN_vkCmdDrawIndirectByteCountEXT cmdDrawIndirectByteCount = nullptr;
    /// VK_EXT_mesh_shader's draws (null without mesh shaders).
    PFN_vkCmdDrawMeshTasksEXT cmdDrawMeshTasks = nullptr;
    PFN_vkCmdDrawMeshTasksIndirectEXT cmdDrawMeshTasksIndirect = nullptr;
    PFN_vkCmdDrawMeshTasksIndirectCountEXT cmdDrawMeshTasksIndirectCount = nullptr;
};

class Device {
public:
    /// Creates the logical device on `physical`, enabling every optional
    /// feature Tessera's backends can use that the device supports
    /// (tessellation, geometry shaders, transform feedback, pipeline
    /// statistics, wireframe, task and mesh shaders). Backends check
    /// features() for what they need.
    static Result<std::unique_ptr<Device>> create(Instance& instance, const PhysicalDeviceInfo& physical);
    ~Device();
    Device(const Device&) = delete;
    Device& operator=(const Device&) = delete;

    VkDevice handle() const { return mDevice; }
    VkPhysicalDevice physical() const { return mPhysical.handle; }
    VkInstance instance() const { return mInstance; }
    VkQueue queue() const { return mQueue; }
    uint32_t queueFamily() const { return mQueueFamily; }
    const device::DeviceFeatures& features() const { return mPhysical.features; }
    const VkPhysicalDeviceProperties& properties() const { return mProperties; }
    const DeviceFunctions& fn() const { return mFn; }

    /// Gives a Vulkan object a name that RenderDoc and validation messages show.
    void setName(VkObjectType type, uint64_t handle, const std::string& name) const;
    template <class T>
    void setName(VkObjectType type, T handle, const std::string& name) const {
        setName(type, reinterpret_cast<uint64_t>(handle), name);
    }
    /// Removes the debug name of an object about to be destroyed. The
    /// validation layer (1.3.239, Debian 12) keeps names of destroyed objects
    /// otherwise, so a long session that makes and destroys objects (a
    /// backend switch, a reloaded world) would grow without bound under it.
    void clearName(VkObjectType type, uint64_t handle) const;
    template <class T>
    void clearName(VkObjectType type, T handle) const {
        clearName(type, reinterpret_cast<uint64_t>(handle));
    }

    /// Opens and closes a labelled region in a command buffer.
    void beginLabel(VkCommandBuffer cmd, const char* name, const float color[4] = nullptr) const;
    void endLabel(VkCommandBuffer cmd) const;

    /// Index of a memory type with `required` properties among `typeBits`;
    /// UINT32_MAX when none.
    uint32_t findMemoryType(uint32_t typeBits, VkMemoryPropertyFlags required) const;
    /// Allocates device memory, named `name`.memory, and accounts for it in
    /// allocatedBytes() until the returned handle frees it. Throws
    /// OutOfDeviceMemory when the driver refuses (out of device or host
    /// memory) or when the allocation would take allocatedBytes() past the
    /// cap of setMemoryCap; the message names `name`, the size and the
    /// memory in use.
    DeviceMemory allocate(const VkMemoryRequirements& req, VkMemoryPropertyFlags flags, const std::string& name);
    /// Frees memory from allocate and takes it off allocatedBytes() (what
    /// DeviceMemory does when it goes).
    void free(VkDeviceMemory memory);
    /// Device memory currently allocated through this device.
    uint64_t allocatedBytes() const { return mAllocatedBytes.load(); }
    /// The most allocatedBytes() has been since the device was created.
    uint64_t peakAllocatedBytes() const { return mPeakBytes.load(); }
    /// Simulates a device with only `bytes` of memory for Tessera (0: no cap,
    /// the default): an allocation that would go past it throws
    /// OutOfDeviceMemory as a real exhaustion would. For the demo's
    /// --device-memory-cap and the exhaustion tests.
    void setMemoryCap(uint64_t bytes) { mMemoryCap = bytes; }
    /// Allocations made since the device was created.
    uint64_t allocationCount() const { return mAllocationCount; }
    /// Fault injection: allocation number `index` (counting from 0 since the
    /// device was created) throws OutOfDeviceMemory as if the driver had
    /// refused it. A cap fails only allocations that raise the memory in use
    /// to a new height; this reaches every one, for the exhaustion tests.
    void failAllocation(uint64_t index) { mFailingAllocation = index; }

    /// Records `record` into a one-shot command buffer, submits it and waits.
    /// Only for what blocks outside a frame: load-time uploads
    /// (Buffer::upload, Image::upload) and readBack (Readback.h); per-frame
    /// work goes through FrameContext.
    void submitImmediate(const std::function<void(VkCommandBuffer)>& record, const char* label);

    /// Runs `destroy` once the GPU can no longer use what it frees: after the
    /// frame slot now recording has retired (or at waitIdle/destruction).
    void deferDestroy(std::function<void()> destroy);
    /// Takes `object` (an RAII owner of GPU objects: a Buffer, an Image, a
    /// unique_ptr to a backend's resources) and destroys it once the frame
    /// slot now recording has retired; what `object` was is left moved-from.
    template <class T>
    void deferRelease(T&& object) {
        auto* doomed = new std::decay_t<T>(std::forward<T>(object));
        deferDestroy([doomed] { delete doomed; });
    }
    /// Called by the frame scheduler when `slot`'s fence has signalled.
    void retireSlot(uint32_t slot);
    /// The frame slot being recorded; set by the frame scheduler.
    void setCurrentSlot(uint32_t slot) { mCurrentSlot = slot; }

    void waitIdle();

private:
    Device() = default;

    VkInstance mInstance = VK_NULL_HANDLE;
    PhysicalDeviceInfo mPhysical;
    VkPhysicalDeviceProperties mProperties{};
    VkPhysicalDeviceMemoryProperties mMemory{};
    VkDevice mDevice = VK_NULL_HANDLE;
    VkQueue mQueue = VK_NULL_HANDLE;
    uint32_t mQueueFamily = 0;
    VkCommandPool mImmediatePool = VK_NULL_HANDLE;
    DeviceFunctions mFn;
    std::atomic<uint64_t> mAllocatedBytes{0};
    std::atomic<uint64_t> mPeakBytes{0};
    uint64_t mMemoryCap = 0;
    uint64_t mAllocationCount = 0;
    uint64_t mFailingAllocation = UINT64_MAX;
    std::unordered_map<VkDeviceMemory, VkDeviceSize> mAllocationSizes; ///< for free's accounting
    uint32_t mCurrentSlot = 0;
    std::vector<std::function<void()>> mDeferred[kFramesInFlight];
};

} // namespace tessera::gpu
