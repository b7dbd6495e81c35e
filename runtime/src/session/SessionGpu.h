#pragma once
/// @file SessionGpu.h
/// The GPU side of a RenderSession for the runtime's own code (the window's
/// overlay): its device, its window and a recorder for the overlay's
/// triangles. RenderSession.h keeps these out of the public headers, which
/// must compile without Vulkan's.

#include "tessera/runtime/RenderSession.h"
#include "tessera/gpu/Device.h"
#include "tessera/gpu/FrameContext.h"

#include <functional>

struct GLFWwindow;

namespace tessera::runtime {

struct SessionGpu {
    /// The device frames render on (null for the null backend).
    static gpu::Device* device(const RenderSession& session);
    /// The window of a windowed session; null headless.
    static GLFWwindow* window(const RenderSession& session);
    /// Called with each frame's context after the backend's passes and
    /// before presentation or readback: the window's overlay records itself
    /// here. An empty function unhooks it.
    static void setOverlayRecorder(RenderSession& session, std::function<void(gpu::FrameContext&)> recorder);
};

} // namespace tessera::runtime
