#include "window/WindowController.h"

#include "session/SessionGpu.h"
#include "tessera/runtime/BackendSelection.h"
#include "tessera/runtime/Reporter.h"
#include "tessera/runtime/SceneRun.h"
#include "tessera/runtime/Settings.h"
#include "tessera/core/ImageFile.h"
#include "tessera/core/Log.h"
#include "tessera/profiler/Profiler.h"

#include <imgui.h>
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cstdio>
#include <iterator>

namespace tessera::runtime {
namespace {

/// Metres ahead of the camera where the meteor control lands a crater.
constexpr float kMeteorDistance = 120.0f;
constexpr float kMeteorRadius = 45.0f;

} // namespace

Result<std::unique_ptr<WindowController>> WindowController::create(SceneRun& run, const Options& options) {
    std::unique_ptr<WindowController> controller(new WindowController(run, options));
    // Before the overlay, whose input callbacks chain to the ones they find.
    if (GLFWwindow* window = SessionGpu::window(run.session()))
        controller->mInput = std::make_unique<WindowInput>(window);
    auto overlay = OverlayContext::create(run.session());
    if (!overlay) return overlay.error();
    controller->mOverlay = std::move(overlay.value());
    OverlayContext* context = controller->mOverlay.get();
    SessionGpu::setOverlayRecorder(run.session(), [context](gpu::FrameContext& frame) { context->record(frame); });
    // Every GPU backend is offered; one the device cannot run says so when picked.
    for (const char* name : kBackendGenerations) controller->mState.backends.push_back(name);
    if (!options.agents.empty()) controller->mState.agents = options.agents.front();
    else controller->mState.agents = 2000;
    controller->mLastFrame = std::chrono::steady_clock::now();
    return controller;
}

WindowController::~WindowController() {
    // The recorder points into the overlay: unhook it before the overlay
    // goes, and let frames in flight finish with its buffers.
    SessionGpu::setOverlayRecorder(mRun.session(), {});
    mRun.session().finish();
}

void WindowController::handleKeys(OverlayActions& actions) {
    if (!mInput) return; // headless --overlay: nothing to press
    mInput->beginFrame();
    WindowInput& in = *mInput;
    // Function keys and Esc never type into a field: they work even while
    // the overlay has the keyboard.
    if (in.pressed(GLFW_KEY_ESCAPE)) in.requestClose();
    if (in.pressed(GLFW_KEY_F1)) {
        mVisible = !mVisible;
        log::info(mVisible ? "overlay shown" : "overlay hidden");
    }
    if (in.pressed(GLFW_KEY_F2)) mRun.liveOptions().wireframe = !mRun.liveOptions().wireframe;
    if (in.pressed(GLFW_KEY_F3)) mRun.liveOptions().lodColors = !mRun.liveOptions().lodColors;
    if (in.pressed(GLFW_KEY_F11)) actions.capture = true;
    if (in.pressed(GLFW_KEY_F12)) actions.screenshot = true;
    if (mOverlay->wantsKeyboard()) return;
    if (in.pressed(GLFW_KEY_TAB)) mState.freeCamera = !mState.freeCamera;
    if (in.pressed(GLFW_KEY_M)) actions.dropMeteor = true;
    const int backendKeys[] = {GLFW_KEY_1, GLFW_KEY_2, GLFW_KEY_3, GLFW_KEY_4};
    for (size_t i = 0; i < mState.backends.size() && i < std::size(backendKeys); ++i)
        if (in.pressed(backendKeys[i]) && mState.backends[i] != mRun.session().capabilities().name)
            actions.switchBackend = mState.backends[i];
}

void WindowController::updateCamera(uint32_t frame, float seconds) {
    if (!mState.freeCamera || !mInput) {
        if (mCameraActive) {
            mRun.world().releaseCamera();
            log::info("camera: the scene's flight");
        }
        mCameraActive = false;
        return;
    }
    if (!mCameraActive) {
        mCamera.setPose(mRun.world().cameraPose(frame)); // take over where the flight is
        log::info("camera: free (WASD/QE, right mouse to look)");
    }
    mCameraActive = true;
    scene::FreeCameraInput input;
    const ImGuiIO& io = ImGui::GetIO();
    if (!mOverlay->wantsKeyboard()) {
        const WindowInput& in = *mInput;
        auto axis = [&in](int plus, int minus) {
            return (in.held(plus) ? 1.0f : 0.0f) - (in.held(minus) ? 1.0f : 0.0f);
        };
        input.forward = axis(GLFW_KEY_W, GLFW_KEY_S);
        input.right = axis(GLFW_KEY_D, GLFW_KEY_A);
        input.up = axis(GLFW_KEY_E, GLFW_KEY_Q);
        input.fast = in.shift();
    }
    if (!mOverlay->wantsMouse() && mInput->mouseHeld(GLFW_MOUSE_BUTTON_RIGHT)) {
        input.lookX = io.MouseDelta.x;
        input.lookY = io.MouseDelta.y;
    }
    mCamera.setSpeed(mState.cameraSpeed);
    // A long frame (a backend switch) must not fling the camera away.
    mCamera.update(input, std::min(seconds, 0.1f));
    mRun.world().fixCamera(mCamera.pose());
    if (input.forward != 0.0f || input.right != 0.0f || input.up != 0.0f) mMoved = true;
    else if (mMoved) {
        // Where a move ended, in --camera's form, so a view found by hand can
        // be replayed headless.
        mMoved = false;
        log::info("camera at " + reporterFor(mOptions).name(setting::kCamera) + " " +
                  scene::formatCameraPose(mCamera.pose()));
    }
}

void WindowController::apply(const OverlayActions& actions) {
    if (!actions.switchBackend.empty()) {
        Status ok = mRun.switchBackend(actions.switchBackend);
        mState.status = ok ? "backend " + actions.switchBackend : reporterFor(mOptions).wording(ok.error());
        if (!ok) reporterFor(mOptions).warning(ok.error());
    }
    if (actions.agents) {
        Options options = mRun.options();
        options.agents = {*actions.agents};
        Status ok = mRun.reloadWorld(options);
        mState.status =
            ok ? "crowd of " + std::to_string(*actions.agents) + " agents" : reporterFor(mOptions).wording(ok.error());
        if (!ok) reporterFor(mOptions).warning(ok.error());
    }
    if (actions.dropMeteor) {
        const scene::Camera& camera = mRun.camera();
        const glm::vec3 at = camera.position() + camera.forward() * kMeteorDistance;
        terrain::CraterSplat splat;
        splat.center = glm::vec2(at.x, at.z);
        splat.radius = kMeteorRadius;
        mRun.world().dropMeteor(splat);
    }
    if (actions.capture) {
        Status ok = mRun.session().requestCapture();
        mState.status = ok ? "capturing the next frame in RenderDoc" : reporterFor(mOptions).wording(ok.error());
    }
    if (actions.screenshot) mScreenshotPending = true;
}

void WindowController::beforeFrame(uint32_t frame) {
    const auto now = std::chrono::steady_clock::now();
    const float seconds = std::chrono::duration<float>(now - mLastFrame).count();
    mLastFrame = now;
    mStats.addCpuFrame(seconds * 1000.0f);
    auto& profiler = profiler::Profiler::global();
    const auto passes = profiler.gpuPasses();
    mStats.addGpuPasses(passes);
    // A window runs for hours: keep only the frames the overlay still needs,
    // unless the run writes a trace or a benchmark of them.
    if (mOptions.capture.empty() && mOptions.benchmark.empty() && frame > 8) profiler.discardFramesBefore(frame - 8);

    OverlayActions actions;
    mOverlay->beginFrame();
    handleKeys(actions);
    if (mVisible) drawOverlayPanel(mRun, mStats, mState, actions);
    // The screenshot shows the scene alone.
    mOverlay->endFrame(mVisible && !actions.screenshot && !mScreenshotPending);
    updateCamera(frame, seconds);
    apply(actions);
}

void WindowController::afterFrame(uint32_t frame) {
    if (!mScreenshotPending) return;
    mScreenshotPending = false;
    char name[64];
    std::snprintf(name, sizeof name, "tessera-screenshot-%05u.png", frame);
    RenderSession& session = mRun.session();
    Status ok = writePng(name, {session.width(), session.height(), session.finish()});
    mState.status = ok ? std::string("wrote ") + name : reporterFor(mOptions).wording(ok.error());
    log::info(mState.status);
}

} // namespace tessera::runtime
