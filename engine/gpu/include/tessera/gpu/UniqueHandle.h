#pragma once
/// @file UniqueHandle.h
/// The one owner of a single Vulkan object in the GPU layer: a named handle
/// that destroys its object (and forgets its debug name) when it goes out of
/// scope or is assigned over, moves but never copies. Buffer, BufferView,
/// Image, Sampler, Pipeline, ComputePipeline, PipelineLayout and the
/// shader modules hold their objects in these, so none of them writes a
/// destructor or move code; a class made of several handles gets its
/// destruction order from the order it declares them in (the last declared
/// goes first).
///
/// The object type (VK_OBJECT_TYPE_*) picks the destroy call; device memory
/// is freed through Device::free, which keeps allocatedBytes() right.

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <type_traits>
#include <utility>

namespace tessera::gpu {

class Device;

namespace detail {

/// Names `handle` (Device::setName) and destroys it: clears the name, then
/// calls the destroy function of `type`. Defined in UniqueHandle.cpp so this
/// header needs no Device.
void nameHandle(const Device& device, VkObjectType type, uint64_t handle, const std::string& name);
void destroyHandle(Device& device, VkObjectType type, uint64_t handle);

template <class VkT>
uint64_t handleBits(VkT handle) {
    // Non-dispatchable handles are pointers on 64-bit platforms, uint64_t elsewhere.
    if constexpr (std::is_pointer_v<VkT>)
        return reinterpret_cast<uint64_t>(handle);
    else
        return uint64_t(handle);
}

} // namespace detail

template <class VkT, VkObjectType kType>
class UniqueHandle {
public:
    UniqueHandle() = default;
    /// Takes ownership of `handle`, made on `device`, and names it `name`
    /// for RenderDoc and the validation layer's messages.
    UniqueHandle(Device& device, VkT handle, const std::string& name) : mDevice(&device), mHandle(handle) {
        detail::nameHandle(device, kType, detail::handleBits(handle), name);
    }
    ~UniqueHandle() { reset(); }
    UniqueHandle(UniqueHandle&& other) noexcept
        : mDevice(std::exchange(other.mDevice, nullptr)), mHandle(std::exchange(other.mHandle, VK_NULL_HANDLE)) {}
    UniqueHandle& operator=(UniqueHandle&& other) noexcept {
        if (this != &other) {
            reset();
            mDevice = std::exchange(other.mDevice, nullptr);
            mHandle = std::exchange(other.mHandle, VK_NULL_HANDLE);
        }
        return *this;
    }
    UniqueHandle(const UniqueHandle&) = delete;
    UniqueHandle& operator=(const UniqueHandle&) = delete;

    VkT get() const { return mHandle; }
    /// The device that owns the object (null when empty).
    Device* device() const { return mDevice; }
    explicit operator bool() const { return mHandle != VK_NULL_HANDLE; }

    /// Destroys the object now; the caller guarantees the GPU is done with it.
    void reset() {
        if (mDevice && mHandle != VK_NULL_HANDLE) detail::destroyHandle(*mDevice, kType, detail::handleBits(mHandle));
        mDevice = nullptr;
        mHandle = VK_NULL_HANDLE;
    }

private:
    Device* mDevice = nullptr;
    VkT mHandle = VK_NULL_HANDLE;
};

/// Device memory from Device::allocate, freed (and uncounted) through Device::free.
using DeviceMemory = UniqueHandle<VkDeviceMemory, VK_OBJECT_TYPE_DEVICE_MEMORY>;

} // namespace tessera::gpu
