#pragma once
/// @file Instance.h
/// The Vulkan instance, the validation layer hook-up and device enumeration.

#include "tessera/device/DeviceFeatures.h"
#include "tessera/core/Result.h"

#include <vulkan/vulkan.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace tessera::gpu {

/// A physical device as the instance sees it.
struct PhysicalDeviceInfo {
    VkPhysicalDevice handle = VK_NULL_HANDLE;
    uint32_t index = 0;
    VkPhysicalDeviceType type = VK_PHYSICAL_DEVICE_TYPE_OTHER;
    uint32_t apiVersion = 0;
    device::DeviceFeatures features;
};

struct InstanceOptions {
    /// Enables VK_LAYER_KHRONOS_validation and counts its messages.
    bool validation = false;
    /// Adds the surface extensions GLFW needs (windowed mode).
    bool windowing = false;
};

class Instance {
public:
    /// Creates the instance. Fails with a clear message when no Vulkan loader
    /// or driver is installed, or validation was asked for but the layer is missing.
    static Result<std::unique_ptr<Instance>> create(const InstanceOptions& options);
    ~Instance();
    Instance(const Instance&) = delete;
    Instance& operator=(const Instance&) = delete;

    VkInstance handle() const { return mInstance; }
    bool validationEnabled() const { return mMessenger != VK_NULL_HANDLE; }
    /// True when created with the surface extensions (windowed mode).
    bool windowingEnabled() const { return mWindowing; }

    /// Devices that support Vulkan 1.3 with dynamic rendering, synchronization2
    /// and push descriptors, which the shared layer requires.
    const std::vector<PhysicalDeviceInfo>& devices() const { return mDevices; }

    /// Picks a device. `selector` is empty (prefer a discrete, then integrated
    /// GPU, then any GPU, then a CPU rasterizer such as lavapipe), a decimal
    /// index into devices(), or a case-insensitive substring of the name.
    Result<PhysicalDeviceInfo> selectDevice(const std::string& selector) const;

    /// Validation warnings and errors seen so far, process-wide.
    static uint64_t validationMessageCount();

private:
    Instance() = default;
    void enumerate();

    VkInstance mInstance = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT mMessenger = VK_NULL_HANDLE;
    bool mWindowing = false;
    std::vector<PhysicalDeviceInfo> mDevices;
};

/// "discrete GPU", "CPU", ...
const char* deviceTypeName(VkPhysicalDeviceType type);

} // namespace tessera::gpu
