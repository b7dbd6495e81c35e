#pragma once
/// @file WindowInput.h
/// The window's keys as the demo's controls read them: every press is
/// queued, so a key pressed and released between two slow frames (a
/// software rasterizer's, or a test's scripted key) still counts once, and
/// held keys and buttons are read from the window's current state.

#include <vector>

struct GLFWwindow;

namespace tessera::runtime {

class WindowInput {
public:
    /// Installs the key callback on `window`; install before a UI library
    /// that chains to the callbacks it finds (Dear ImGui's GLFW backend).
    explicit WindowInput(GLFWwindow* window);
    ~WindowInput();
    WindowInput(const WindowInput&) = delete;
    WindowInput& operator=(const WindowInput&) = delete;

    /// Takes the presses queued since the last call as this frame's.
    void beginFrame();
    /// Whether `key` (a GLFW key code) was pressed since the last frame.
    bool pressed(int key) const;
    /// Whether `key` is down now.
    bool held(int key) const;
    /// Whether mouse button `button` (GLFW numbering) is down now.
    bool mouseHeld(int button) const;
    bool shift() const;
    /// Asks the window to close (the frame loop ends after this frame).
    void requestClose();

private:
    static void onKey(GLFWwindow* window, int key, int scancode, int action, int mods);

    GLFWwindow* mWindow;
    std::vector<int> mQueued;
    std::vector<int> mPressed;
};

} // namespace tessera::runtime
