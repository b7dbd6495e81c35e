#pragma once
/// @file SubdivTestHost.h
/// Test support: the least host that draws subdivision surfaces through a
/// backend plugin on the shared test device (GpuTestDevice, validation on):
/// the plugin loaded from the build tree, an offscreen target, a frame
/// scheduler, and one frame at a time with its pixels read back.

#include "tessera/backend/BackendRegistry.h"
#include "tessera/backend/SubdivDesc.h"
#include "tessera/core/Result.h"
#include "tessera/gpu/Device.h"
#include "tessera/gpu/FrameScheduler.h"
#include "tessera/gpu/RenderTarget.h"
#include "tessera/scene/Camera.h"

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace tessera::test {

class SubdivTestHost {
public:
    /// Loads and initializes backend `name` on `device` with a target of
    /// width x height; the error says why it cannot.
    static Result<std::unique_ptr<SubdivTestHost>> create(gpu::Device& device, const std::string& name,
                                                          uint32_t width, uint32_t height);
    ~SubdivTestHost();

    backend::Backend& backend() { return *mBackend; }
    uint32_t width() const { return mTarget->width(); }
    uint32_t height() const { return mTarget->height(); }

    /// One frame from `camera` drawing `draws` (surface, uniforms), filled
    /// or as wireframe; returns its RGBA8 pixels, rows top to bottom, after
    /// the GPU finished.
    std::vector<uint8_t> drawFrame(const scene::Camera& camera,
                                   std::span<const std::pair<backend::SubdivHandle, backend::SubdivDrawInfo>> draws,
                                   bool wireframe = false);

private:
    SubdivTestHost() = default;

    backend::BackendRegistry mRegistry;
    backend::BackendPtr mBackend;
    std::unique_ptr<gpu::RenderTarget> mTarget;
    std::unique_ptr<gpu::FrameScheduler> mScheduler;
    uint64_t mFrame = 0;
};

} // namespace tessera::test
