#include "tessera/gpu/Device.h"

#include "tessera/core/OutOfDeviceMemory.h"
#include "tessera/gpu/VulkanCheck.h"

#include <algorithm>
#include <cstdio>
#include <cstring>

namespace tessera::gpu {
namespace {

bool hasExtension(VkPhysicalDevice device, const char* name) {
    uint32_t count = 0;
    vkEnumerateDeviceExtensionProperties(device, nullptr, &count, nullptr);
    std::vector<VkExtensionProperties> exts(count);
    vkEnumerateDeviceExtensionProperties(device, nullptr, &count, exts.data());
    return std::any_of(exts.begin(), exts.end(), [&](const auto& e) { return std::strcmp(e.extensionName, name) == 0; });
}

std::string mebibytes(uint64_t bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f MiB", double(bytes) / (1024.0 * 1024.0));
    return text;
}

template <class Fn>
Fn load(VkDevice device, const char* name) {
    return reinterpret_cast<Fn>(vkGetDeviceProcAddr(device, name));
}

/// The extension entry points Tessera calls, loaded once for `device`.
DeviceFunctions loadFunctions(VkInstance instance, VkDevice device, const device::DeviceFeatures& enabled) {
    DeviceFunctions fn;
    fn.cmdPushDescriptorSet = load<PFN_vkCmdPushDescriptorSetKHR>(device, "vkCmdPushDescriptorSetKHR");
    // Debug-utils entry points come from the instance extension; the loader
    // hands out device-level trampolines for them.
    fn.setObjectName = reinterpret_cast<PFN_vkSetDebugUtilsObjectNameEXT>(
        vkGetInstanceProcAddr(instance, "vkSetDebugUtilsObjectNameEXT"));
    fn.cmdBeginLabel = reinterpret_cast<PFN_vkCmdBeginDebugUtilsLabelEXT>(
        vkGetInstanceProcAddr(instance, "vkCmdBeginDebugUtilsLabelEXT"));
    fn.cmdEndLabel = reinterpret_cast<PFN_vkCmdEndDebugUtilsLabelEXT>(
        vkGetInstanceProcAddr(instance, "vkCmdEndDebugUtilsLabelEXT"));
    fn.cmdInsertLabel = reinterpret_cast<PFN_vkCmdInsertDebugUtilsLabelEXT>(
        vkGetInstanceProcAddr(instance, "vkCmdInsertDebugUtilsLabelEXT"));
    if (enabled.transformFeedback) {
        fn.cmdBindTransformFeedbackBuffers =
            load<PFN_vkCmdBindTransformFeedbackBuffersEXT>(device, "vkCmdBindTransformFeedbackBuffersEXT");
        fn.cmdBeginTransformFeedback = load<PFN_vkCmdBeginTransformFeedbackEXT>(device, "vkCmdBeginTransformFeedbackEXT");
        fn.cmdEndTransformFeedback = load<PFN_vkCmdEndTransformFeedbackEXT>(device, "vkCmdEndTransformFeedbackEXT");
        fn.cmdDrawIndirectByteCount = load<PFN_vkCmdDrawIndirectByteCountEXT>(device, "vkCmdDrawIndirectByteCountEXT");
    }
    if (enabled.meshShader) {
        fn.cmdDrawMeshTasks = load<PFN_vkCmdDrawMeshTasksEXT>(device, "vkCmdDrawMeshTasksEXT");
        fn.cmdDrawMeshTasksIndirect = load<PFN_vkCmdDrawMeshTasksIndirectEXT>(device, "vkCmdDrawMeshTasksIndirectEXT");
        fn.cmdDrawMeshTasksIndirectCount =
            load<PFN_vkCmdDrawMeshTasksIndirectCountEXT>(device, "vkCmdDrawMeshTasksIndirectCountEXT");
    }
    return fn;
}

} // namespace

Result<std::unique_ptr<Device>> Device::create(Instance& instance, const PhysicalDeviceInfo& physical) {
    std::unique_ptr<Device> device(new Device());
    device->mInstance = instance.handle();
    device->mPhysical = physical;
    VkPhysicalDevice pd = physical.handle;
    vkGetPhysicalDeviceProperties(pd, &device->mProperties);
    vkGetPhysicalDeviceMemoryProperties(pd, &device->mMemory);

    uint32_t familyCount = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(pd, &familyCount, nullptr);
    std::vector<VkQueueFamilyProperties> families(familyCount);
    vkGetPhysicalDeviceQueueFamilyProperties(pd, &familyCount, families.data());
    uint32_t family = UINT32_MAX;
    for (uint32_t i = 0; i < familyCount; ++i) {
        if ((families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) && (families[i].queueFlags & VK_QUEUE_COMPUTE_BIT)) {
            family = i;
            break;
        }
    }
    if (family == UINT32_MAX) return fail(physical.features.deviceName, ": no graphics+compute queue");
    device->mQueueFamily = family;
    // A queue family without timestamp bits cannot time passes, whatever the limits say.
    if (families[family].timestampValidBits == 0) device->mPhysical.features.timestamps = false;

    const auto& want = physical.features;
    VkPhysicalDeviceFeatures core{};
    core.tessellationShader = want.tessellationShader;
    core.geometryShader = want.geometryShader;
    core.fillModeNonSolid = want.fillModeNonSolid;
    core.pipelineStatisticsQuery = want.pipelineStatistics;
    core.vertexPipelineStoresAndAtomics = want.vertexStores;
    core.multiDrawIndirect = want.multiDrawIndirect;
    core.drawIndirectFirstInstance = want.multiDrawIndirect;

    VkPhysicalDeviceTransformFeedbackFeaturesEXT xfb{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_TRANSFORM_FEEDBACK_FEATURES_EXT};
    xfb.transformFeedback = VK_TRUE;
    VkPhysicalDeviceVulkan13Features v13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    v13.dynamicRendering = VK_TRUE;
    v13.synchronization2 = VK_TRUE;
    // Required by Vulkan 1.3; glslang's vulkan1.3 target declares compute
    // workgroup sizes with LocalSizeId, which needs it enabled.
    v13.maintenance4 = VK_TRUE;
    if (want.transformFeedback) v13.pNext = &xfb;
    // Task and mesh stages where the device has them (and they are not
    // hidden), so a hidden feature stays off for the validation layer too.
    VkPhysicalDeviceMeshShaderFeaturesEXT mesh{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MESH_SHADER_FEATURES_EXT};
    mesh.taskShader = VK_TRUE;
    mesh.meshShader = VK_TRUE;
    mesh.meshShaderQueries = want.meshShaderQueries;
    if (want.meshShader) {
        mesh.pNext = v13.pNext;
        v13.pNext = &mesh;
    }
    VkPhysicalDeviceFeatures2 features2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &v13};
    features2.features = core;

    std::vector<const char*> extensions = {VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME};
    if (want.transformFeedback) extensions.push_back(VK_EXT_TRANSFORM_FEEDBACK_EXTENSION_NAME);
    if (want.meshShader) extensions.push_back(VK_EXT_MESH_SHADER_EXTENSION_NAME);
    // The swapchain extension needs the instance's surface extension, which
    // only windowed runs enable.
    if (instance.windowingEnabled() && hasExtension(pd, VK_KHR_SWAPCHAIN_EXTENSION_NAME)) extensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);

    const float priority = 1.0f;
    VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queueInfo.queueFamilyIndex = family;
    queueInfo.queueCount = 1;
    queueInfo.pQueuePriorities = &priority;

    VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO, &features2};
    info.queueCreateInfoCount = 1;
    info.pQueueCreateInfos = &queueInfo;
    info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    VkResult result = vkCreateDevice(pd, &info, nullptr, &device->mDevice);
    if (result != VK_SUCCESS)
        return fail(physical.features.deviceName, ": could not create the Vulkan device (", resultName(result), ")");
    vkGetDeviceQueue(device->mDevice, family, 0, &device->mQueue);

    device->mFn = loadFunctions(instance.handle(), device->mDevice, want);
    VkDevice d = device->mDevice;

    VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    poolInfo.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
    poolInfo.queueFamilyIndex = family;
    TESSERA_VK_CHECK(vkCreateCommandPool(d, &poolInfo, nullptr, &device->mImmediatePool));
    device->setName(VK_OBJECT_TYPE_COMMAND_POOL, device->mImmediatePool, "device.immediatePool");
    device->setName(VK_OBJECT_TYPE_DEVICE, device->mDevice, "tessera.device");
    device->setName(VK_OBJECT_TYPE_QUEUE, device->mQueue, "tessera.graphicsQueue");
    return device;
}

Device::~Device() {
    if (!mDevice) return;
    waitIdle();
    vkDestroyCommandPool(mDevice, mImmediatePool, nullptr);
    vkDestroyDevice(mDevice, nullptr);
}

void Device::waitIdle() {
    if (!mDevice) return;
    TESSERA_VK_CHECK(vkDeviceWaitIdle(mDevice));
    for (uint32_t slot = 0; slot < kFramesInFlight; ++slot) retireSlot(slot);
}

void Device::setName(VkObjectType type, uint64_t handle, const std::string& name) const {
    if (!mFn.setObjectName || handle == 0) return;
    VkDebugUtilsObjectNameInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT};
    info.objectType = type;
    info.objectHandle = handle;
    info.pObjectName = name.c_str();
    mFn.setObjectName(mDevice, &info);
}

void Device::clearName(VkObjectType type, uint64_t handle) const {
    if (!mFn.setObjectName || handle == 0) return;
    VkDebugUtilsObjectNameInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT};
    info.objectType = type;
    info.objectHandle = handle;
    info.pObjectName = nullptr; // no name: the layer forgets the object's entry
    mFn.setObjectName(mDevice, &info);
}

void Device::beginLabel(VkCommandBuffer cmd, const char* name, const float color[4]) const {
    if (!mFn.cmdBeginLabel) return;
    VkDebugUtilsLabelEXT label{VK_STRUCTURE_TYPE_DEBUG_UTILS_LABEL_EXT};
    label.pLabelName = name;
    if (color) std::memcpy(label.color, color, sizeof label.color);
    mFn.cmdBeginLabel(cmd, &label);
}

void Device::endLabel(VkCommandBuffer cmd) const {
    if (mFn.cmdEndLabel) mFn.cmdEndLabel(cmd);
}

uint32_t Device::findMemoryType(uint32_t typeBits, VkMemoryPropertyFlags required) const {
    for (uint32_t i = 0; i < mMemory.memoryTypeCount; ++i)
        if ((typeBits & (1u << i)) && (mMemory.memoryTypes[i].propertyFlags & required) == required) return i;
    return UINT32_MAX;
}

DeviceMemory Device::allocate(const VkMemoryRequirements& req, VkMemoryPropertyFlags flags, const std::string& name) {
    uint32_t type = findMemoryType(req.memoryTypeBits, flags);
    // Cached readback memory is a preference, not a requirement.
    if (type == UINT32_MAX && (flags & VK_MEMORY_PROPERTY_HOST_CACHED_BIT))
        type = findMemoryType(req.memoryTypeBits, flags & ~VK_MEMORY_PROPERTY_HOST_CACHED_BIT);
    if (type == UINT32_MAX) fatalVulkanError(("no memory type for " + name).c_str(), VK_ERROR_OUT_OF_DEVICE_MEMORY);
    const uint64_t inUse = mAllocatedBytes.load();
    // One message for every way to run out: what, how much, against what.
    auto outOfMemory = [&](const std::string& cause) {
        const std::string limit = mMemoryCap ? " of the " + mebibytes(mMemoryCap) + " cap" : std::string();
        return OutOfDeviceMemory("out of device memory: " + name + " needs " + mebibytes(req.size) + " with " +
                                     mebibytes(inUse) + limit + " in use on " + mPhysical.features.deviceName + cause,
                                 name, req.size, inUse, mMemoryCap);
    };
    if (mAllocationCount++ == mFailingAllocation)
        throw outOfMemory(" (allocation " + std::to_string(mFailingAllocation) + " failed on purpose)");
    if (mMemoryCap && inUse + req.size > mMemoryCap) throw outOfMemory("");
    VkMemoryAllocateInfo info{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    info.allocationSize = req.size;
    info.memoryTypeIndex = type;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    const VkResult result = vkAllocateMemory(mDevice, &info, nullptr, &memory);
    if (result == VK_ERROR_OUT_OF_DEVICE_MEMORY || result == VK_ERROR_OUT_OF_HOST_MEMORY)
        throw outOfMemory(std::string(" (") + resultName(result) + ")");
    TESSERA_VK_CHECK(result);
    DeviceMemory owned(*this, memory, name + ".memory");
    mAllocationSizes.emplace(memory, req.size);
    const uint64_t now = (mAllocatedBytes += req.size);
    uint64_t peak = mPeakBytes.load();
    while (now > peak && !mPeakBytes.compare_exchange_weak(peak, now)) {
    }
    return owned;
}

void Device::free(VkDeviceMemory memory) {
    if (!memory) return;
    const auto size = mAllocationSizes.find(memory);
    clearName(VK_OBJECT_TYPE_DEVICE_MEMORY, memory);
    vkFreeMemory(mDevice, memory, nullptr);
    if (size == mAllocationSizes.end()) return;
    mAllocatedBytes -= size->second;
    mAllocationSizes.erase(size);
}

void Device::submitImmediate(const std::function<void(VkCommandBuffer)>& record, const char* label) {
    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = mImmediatePool;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    TESSERA_VK_CHECK(vkAllocateCommandBuffers(mDevice, &alloc, &cmd));
    setName(VK_OBJECT_TYPE_COMMAND_BUFFER, cmd, label);
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    TESSERA_VK_CHECK(vkBeginCommandBuffer(cmd, &begin));
    beginLabel(cmd, label);
    record(cmd);
    endLabel(cmd);
    TESSERA_VK_CHECK(vkEndCommandBuffer(cmd));

    VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VkFence fence = VK_NULL_HANDLE;
    TESSERA_VK_CHECK(vkCreateFence(mDevice, &fenceInfo, nullptr, &fence));
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &cmd;
    TESSERA_VK_CHECK(vkQueueSubmit(mQueue, 1, &submit, fence));
    TESSERA_VK_CHECK(vkWaitForFences(mDevice, 1, &fence, VK_TRUE, UINT64_MAX));
    vkDestroyFence(mDevice, fence, nullptr);
    clearName(VK_OBJECT_TYPE_COMMAND_BUFFER, cmd);
    vkFreeCommandBuffers(mDevice, mImmediatePool, 1, &cmd);
}

void Device::deferDestroy(std::function<void()> destroy) { mDeferred[mCurrentSlot].push_back(std::move(destroy)); }

void Device::retireSlot(uint32_t slot) {
    auto pending = std::move(mDeferred[slot]);
    mDeferred[slot].clear();
    for (auto& destroy : pending) destroy();
}

} // namespace tessera::gpu
