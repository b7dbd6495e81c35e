#pragma once
/// @file OutOfDeviceMemory.h
/// The one exception Tessera's Vulkan layer throws: a device-memory
/// allocation that did not fit. Declared in the core, Vulkan-free, so a host
/// (the runtime, a game embedding it, its tests) catches it without
/// including the GPU layer.
///
/// Tessera reports what a user can get wrong through Result (Result.h). Device
/// memory running out is different: it can happen in any constructor of a
/// buffer or image, deep inside a backend's upload or in the middle of a
/// frame, where threading a Result through every object would hide the
/// resource code under error plumbing. So it is treated like std::bad_alloc:
/// Device::allocate throws, every GPU object releases what it made as the
/// stack unwinds (RAII; the backend contract requires it, docs/ARCHITECTURE.md
/// "The backend contract"), and the host catches it at the top of the run, prints what()
/// and exits non-zero. The validation layer's object tracking then finds
/// nothing left behind (tests/runtime/device_memory_exhaustion_test.cpp).
///
/// It comes either from the driver (VK_ERROR_OUT_OF_DEVICE_MEMORY or
/// VK_ERROR_OUT_OF_HOST_MEMORY) or from the cap a host sets with
/// Device::setMemoryCap (the demo's --device-memory-cap), which simulates a
/// smaller device.

#include <cstdint>
#include <stdexcept>
#include <string>

namespace tessera {

class OutOfDeviceMemory : public std::runtime_error {
public:
    /// `what` is the whole message; the numbers are kept for hosts and tests
    /// that act on them (the exhaustion sweep walks the allocations with them).
    OutOfDeviceMemory(const std::string& what, std::string allocation, uint64_t requestedBytes, uint64_t inUseBytes,
                      uint64_t capBytes)
        : std::runtime_error(what), mAllocation(std::move(allocation)), mRequested(requestedBytes), mInUse(inUseBytes),
          mCap(capBytes) {}
    ~OutOfDeviceMemory() override; // out of line: one home for the vtable and type info (core)

    /// The debug name of the buffer or image that did not fit.
    const std::string& allocation() const { return mAllocation; }
    /// Bytes the allocation asked for.
    uint64_t requestedBytes() const { return mRequested; }
    /// Bytes the device held through Tessera when it was asked.
    uint64_t inUseBytes() const { return mInUse; }
    /// The cap in force (Device::setMemoryCap); 0 when the driver refused
    /// with no cap set.
    uint64_t capBytes() const { return mCap; }

private:
    std::string mAllocation;
    uint64_t mRequested = 0;
    uint64_t mInUse = 0;
    uint64_t mCap = 0;
};

} // namespace tessera
