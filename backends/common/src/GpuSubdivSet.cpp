#include "common/GpuSubdivSet.h"

#include "tessera/gpu/Device.h"

namespace tessera::backends {

Result<backend::SubdivHandle> GpuSubdivSet::create(const backend::SubdivDesc& desc) {
    if (!mDevice) return Error{"createSubdiv before initialize"};
    auto created = GpuSubdiv::create(*mDevice, desc, mWriteUsage);
    if (!created) return created.error();
    mSurfaces.push_back(std::move(created.value()));
    return backend::SubdivHandle{static_cast<uint32_t>(mSurfaces.size() - 1)};
}

void GpuSubdivSet::destroy(backend::SubdivHandle handle) {
    if (!find(handle)) return;
    GpuSubdiv* released = mSurfaces[handle.id].release();
    mDevice->deferDestroy([released] { delete released; });
}

GpuSubdiv* GpuSubdivSet::find(backend::SubdivHandle handle) {
    return handle.valid() && handle.id < mSurfaces.size() ? mSurfaces[handle.id].get() : nullptr;
}

Result<backend::SubdivPoints> GpuSubdivSet::readPoints(backend::SubdivHandle handle) {
    GpuSubdiv* surface = find(handle);
    if (!surface) return Error{"readSubdivPoints: no such surface"};
    return backend::SubdivPoints{surface->readPoints()};
}

} // namespace tessera::backends
