#pragma once
/// @file GpuTestDevice.h
/// Test support: one Vulkan instance (with the validation layer) and device
/// shared by a test binary's GPU tests, on the default device (lavapipe on CI).

#include "tessera/gpu/Device.h"
#include "tessera/gpu/Instance.h"

#include <memory>
#include <string>

namespace tessera::test {

class GpuTestDevice {
public:
    /// The shared device, created on first use; null with the reason in
    /// `why` when no Vulkan device can be created.
    static gpu::Device* get(std::string& why);
    /// Validation messages since the process started.
    static uint64_t validationMessages() { return gpu::Instance::validationMessageCount(); }
};

} // namespace tessera::test
