#pragma once
/// @file BackendInitInfo.h
/// What Backend::initialize receives from the host.

#include "tessera/device/DeviceFeatures.h"

#include <filesystem>

namespace tessera::gpu {
class Device;
}

namespace tessera::backend {

struct BackendInitInfo {
    /// The shared Vulkan device; null for the null backend.
    gpu::Device* device = nullptr;
    /// The features of `device` (empty for the null backend).
    device::DeviceFeatures features;
    /// Format of the color target the host renders into (a VkFormat value,
    /// kept as an integer so this header stays Vulkan-free).
    uint32_t colorFormat = 0;
    uint32_t depthFormat = 0;
};

} // namespace tessera::backend
