#pragma once
/// @file WindowController.h
/// What --window adds to the frame loop: the Dear ImGui overlay with its
/// statistics and controls, a free camera (WASD and mouse) beside the
/// scripted flight, backend switching at run time, and screenshots and
/// RenderDoc captures from keys. Headless runs never make one.

#include "window/FrameStats.h"
#include "window/OverlayActions.h"
#include "window/OverlayContext.h"
#include "window/OverlayPanel.h"
#include "window/WindowInput.h"
#include "tessera/runtime/Options.h"
#include "tessera/core/Result.h"
#include "tessera/scene/FreeCamera.h"

#include <chrono>
#include <memory>

namespace tessera::runtime {

class SceneRun;

class WindowController {
public:
    /// Binds the overlay to `run`'s window; an error when it has none.
    static Result<std::unique_ptr<WindowController>> create(SceneRun& run, const Options& options);
    ~WindowController();
    WindowController(const WindowController&) = delete;
    WindowController& operator=(const WindowController&) = delete;

    /// Before frame `frame`: keys and mouse, the overlay's windows, the
    /// camera, then what the controls asked for (a backend switch, a new
    /// crowd, a meteor, a capture).
    void beforeFrame(uint32_t frame);
    /// Whether this frame must be read back (a screenshot was asked for).
    bool wantsReadback() const { return mScreenshotPending; }
    /// After the frame: writes the screenshot asked for, if any.
    void afterFrame(uint32_t frame);

private:
    WindowController(SceneRun& run, const Options& options) : mRun(run), mOptions(options) {}
    void handleKeys(OverlayActions& actions);
    void updateCamera(uint32_t frame, float seconds);
    void apply(const OverlayActions& actions);

    SceneRun& mRun;
    Options mOptions;
    std::unique_ptr<WindowInput> mInput; ///< before mOverlay, which chains to its callback
    std::unique_ptr<OverlayContext> mOverlay;
    FrameStats mStats;
    OverlayState mState;
    scene::FreeCamera mCamera;
    bool mCameraActive = false;
    bool mMoved = false;
    bool mVisible = true;
    bool mScreenshotPending = false;
    std::chrono::steady_clock::time_point mLastFrame;
};

} // namespace tessera::runtime
