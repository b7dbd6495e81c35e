#pragma once
/// @file GpuObjectTable.h
/// How every GPU backend stores the objects the contract hands out handles
/// for (terrains, characters, crowds, subdivision surfaces): the handle's id
/// is the index of the object in one table, ids are never reused, a
/// destroyed object's entry stays empty, and an object is released only
/// after the frame now recording (which may still read it) has retired.

#include "tessera/core/Result.h"
#include "tessera/gpu/Device.h"

#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace tessera::backends {

template <class Object, class Handle>
class GpuObjectTable {
public:
    /// Stores `object` under the next id.
    Handle add(std::unique_ptr<Object> object) {
        mObjects.push_back(std::move(object));
        return Handle{static_cast<uint32_t>(mObjects.size() - 1)};
    }
    /// Stores `object`, then lets the backend attach its technique's resources
    /// to it (`attach(Object&, Handle)` returning Status); when that fails,
    /// destroys the object again and returns the error. The id stays used.
    template <class Attach>
    Result<Handle> add(gpu::Device& device, std::unique_ptr<Object> object, Attach&& attach) {
        Object& stored = *object;
        const Handle handle = add(std::move(object));
        if (Status attached = attach(stored, handle); !attached) {
            destroy(device, handle);
            return attached.error();
        }
        return handle;
    }
    /// The object, or null for an unknown or destroyed handle.
    Object* find(Handle handle) const {
        return handle.valid() && handle.id < mObjects.size() ? mObjects[handle.id].get() : nullptr;
    }
    /// Releases the object once the frame now recording has retired
    /// (Device::deferRelease); unknown handles are ignored.
    void destroy(gpu::Device& device, Handle handle) {
        if (find(handle)) device.deferRelease(std::move(mObjects[handle.id]));
    }
    /// Releases every object now (shutdown: the device is idle).
    void clear() { mObjects.clear(); }
    /// Ids handed out so far, destroyed ones included.
    uint32_t size() const { return static_cast<uint32_t>(mObjects.size()); }

private:
    std::vector<std::unique_ptr<Object>> mObjects; ///< null once destroyed
};

} // namespace tessera::backends
