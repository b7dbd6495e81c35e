#pragma once
/// @file GpuSubdivSet.h
/// A backend's subdivision surfaces: the handle table behind createSubdiv,
/// destroySubdiv, updateSubdivTiles and readSubdivPoints, the same for
/// every GPU backend (each only names how its refine pass writes points).

#include "common/GpuSubdiv.h"
#include "tessera/backend/SubdivDesc.h"
#include "tessera/core/Result.h"

#include <memory>
#include <vector>

namespace tessera::backends {

class GpuSubdivSet {
public:
    GpuSubdivSet() = default;
    GpuSubdivSet(gpu::Device& device, VkBufferUsageFlags writeUsage) : mDevice(&device), mWriteUsage(writeUsage) {}

    Result<backend::SubdivHandle> create(const backend::SubdivDesc& desc);
    /// Destroys a surface once the frames that use it have retired.
    void destroy(backend::SubdivHandle handle);
    /// The surface, or null for an unknown or destroyed handle.
    GpuSubdiv* find(backend::SubdivHandle handle);
    /// Destroys every surface now (shutdown: the device is idle).
    void clear() { mSurfaces.clear(); }
    /// Blocking read of a surface's refined points.
    Result<backend::SubdivPoints> readPoints(backend::SubdivHandle handle);

private:
    gpu::Device* mDevice = nullptr;
    VkBufferUsageFlags mWriteUsage = 0;
    std::vector<std::unique_ptr<GpuSubdiv>> mSurfaces; ///< null once destroyed
};

} // namespace tessera::backends
