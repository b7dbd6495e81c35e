#pragma once
/// @file VulkanCheck.h
/// Error handling for Vulkan calls.
///
/// Creation-time failures a user can cause (no device, missing feature) are
/// returned as Result errors by the functions that create things. A failure in
/// the middle of a frame (device lost, out of memory) cannot be recovered from
/// here, so it ends the process with a message naming the call, never silently.

#include <vulkan/vulkan.h>

namespace tessera::gpu {

/// Readable name of a VkResult ("VK_ERROR_DEVICE_LOST").
const char* resultName(VkResult result);

/// Prints "<what> failed: <VkResult>" and exits with status 3.
[[noreturn]] void fatalVulkanError(const char* what, VkResult result);

} // namespace tessera::gpu

/// Checks a VkResult that can only fail on a broken device or driver.
#define TESSERA_VK_CHECK(call)                                                     \
    do {                                                                           \
        VkResult tesseraVkResult_ = (call);                                        \
        if (tesseraVkResult_ < 0) ::tessera::gpu::fatalVulkanError(#call, tesseraVkResult_); \
    } while (0)
