#include "window/WindowInput.h"

#include <GLFW/glfw3.h>

#include <algorithm>

namespace tessera::runtime {

WindowInput::WindowInput(GLFWwindow* window) : mWindow(window) {
    glfwSetWindowUserPointer(mWindow, this);
    glfwSetKeyCallback(mWindow, &WindowInput::onKey);
}

WindowInput::~WindowInput() {
    glfwSetKeyCallback(mWindow, nullptr);
    glfwSetWindowUserPointer(mWindow, nullptr);
}

void WindowInput::onKey(GLFWwindow* window, int key, int, int action, int) {
    auto* self = static_cast<WindowInput*>(glfwGetWindowUserPointer(window));
    if (self && action == GLFW_PRESS) self->mQueued.push_back(key);
}

void WindowInput::beginFrame() {
    mPressed.swap(mQueued);
    mQueued.clear();
}

bool WindowInput::pressed(int key) const { return std::find(mPressed.begin(), mPressed.end(), key) != mPressed.end(); }

bool WindowInput::held(int key) const { return glfwGetKey(mWindow, key) == GLFW_PRESS; }

bool WindowInput::mouseHeld(int button) const { return glfwGetMouseButton(mWindow, button) == GLFW_PRESS; }

void WindowInput::requestClose() { glfwSetWindowShouldClose(mWindow, GLFW_TRUE); }

bool WindowInput::shift() const { return held(GLFW_KEY_LEFT_SHIFT) || held(GLFW_KEY_RIGHT_SHIFT); }

} // namespace tessera::runtime
