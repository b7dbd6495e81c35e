#pragma once
/// @file OverlayContext.h
/// The window's Dear ImGui context: GLFW input in, triangle lists out to the
/// GPU layer's UiRenderer, recorded after the backend's passes.

#include "tessera/core/Result.h"
#include "tessera/gpu/UiRenderer.h"

#include <memory>
#include <vector>

struct ImGuiContext;

namespace tessera::gpu {
class FrameContext;
}

namespace tessera::runtime {

class RenderSession;

class OverlayContext {
public:
    /// Creates the context on the session's device, with the window's input
    /// when it has one (headless, the target is the display); an error on
    /// the null backend.
    static Result<std::unique_ptr<OverlayContext>> create(RenderSession& session);
    ~OverlayContext();
    OverlayContext(const OverlayContext&) = delete;
    OverlayContext& operator=(const OverlayContext&) = delete;

    /// Starts the UI frame (input from GLFW); build windows after it.
    void beginFrame();
    /// Ends the UI frame and keeps its triangles for record(); with
    /// `visible` false nothing is drawn this frame.
    void endFrame(bool visible);
    /// Records the kept triangles over the frame (RenderSession's overlay hook).
    void record(gpu::FrameContext& frame);

    /// Whether the UI takes the mouse or the keyboard this frame (over a
    /// window, typing in a field): camera controls leave them alone then.
    bool wantsMouse() const;
    bool wantsKeyboard() const;

private:
    OverlayContext() = default;

    ImGuiContext* mContext = nullptr;
    bool mGlfwBound = false;
    float mHeadlessWidth = 0.0f, mHeadlessHeight = 0.0f;
    gpu::UiRenderer mRenderer;
    std::vector<gpu::UiVertex> mVertices;
    std::vector<uint16_t> mIndices;
    std::vector<gpu::UiDrawCommand> mCommands;
    gpu::UiDrawData mData;
};

} // namespace tessera::runtime
