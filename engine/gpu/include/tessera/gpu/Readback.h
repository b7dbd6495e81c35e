#pragma once
/// @file Readback.h
/// The one way to read GPU data back to the host outside a frame: the
/// blocking reads of the backend contract (readTerrainHeights,
/// readCrowdTiers, readSubdivPoints), for tests and tools. Per-frame
/// readbacks (FrameReport's counts) copy into a frame slot's host-visible
/// buffer instead and are read when the slot's fence has signalled.

#include <vulkan/vulkan.h>

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace tessera::gpu {

class Buffer;
class Device;

/// Waits until the device is idle (every frame in flight retired), then
/// records `record` into a one-shot command buffer labelled `label`,
/// submits it and waits for it (Device::submitImmediate). `record` copies
/// into `destination`, a host-visible buffer of `bytes` bytes named `name`,
/// whose contents are returned.
std::vector<std::byte> readBack(Device& device, VkDeviceSize bytes, const std::string& name, const char* label,
                                const std::function<void(VkCommandBuffer cmd, const Buffer& destination)>& record);

} // namespace tessera::gpu
