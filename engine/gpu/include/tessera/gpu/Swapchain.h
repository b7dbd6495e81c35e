#pragma once
/// @file Swapchain.h
/// A GLFW window and its swapchain, for `--window`. Frames are rendered
/// offscreen and blitted here, so windowed and headless pixels match.

#include "tessera/core/Result.h"

#include <vulkan/vulkan.h>

#include <memory>
#include <string>
#include <vector>

struct GLFWwindow;

namespace tessera::gpu {

class Device;
class Instance;
class RenderTarget;

class Swapchain {
public:
    /// Opens a window. Fails with a message when no display is available.
    static Result<std::unique_ptr<Swapchain>> create(Instance& instance, Device& device, uint32_t width,
                                                     uint32_t height, const std::string& title);
    ~Swapchain();

    /// True once the user closed the window.
    bool shouldClose() const;
    /// Processes window events; returns true when the framebuffer size changed.
    bool pollEvents();
    /// The GLFW window, for a host's input handling (the overlay's).
    GLFWwindow* window() const { return mWindow; }
    uint32_t width() const { return mExtent.width; }
    uint32_t height() const { return mExtent.height; }

    /// Acquires the next image; false when the swapchain must be recreated.
    bool acquire(VkSemaphore& imageAvailable);
    /// Blits `target` into the acquired image and transitions it for presenting.
    void recordPresentBlit(VkCommandBuffer cmd, RenderTarget& target);
    VkSemaphore renderFinished() const;
    /// Presents the acquired image; false when the swapchain must be recreated.
    bool present();
    /// Rebuilds the swapchain for the window's current size.
    void recreate();

    static bool initWindowSystem();

private:
    Swapchain(Instance& instance, Device& device) : mInstance(instance), mDevice(device) {}
    Status build();
    void destroySwapchain();

    Instance& mInstance;
    Device& mDevice;
    GLFWwindow* mWindow = nullptr;
    VkSurfaceKHR mSurface = VK_NULL_HANDLE;
    VkSwapchainKHR mSwapchain = VK_NULL_HANDLE;
    VkFormat mFormat = VK_FORMAT_UNDEFINED;
    VkExtent2D mExtent{};
    std::vector<VkImage> mImages;
    std::vector<VkSemaphore> mAcquire;
    std::vector<VkSemaphore> mFinished;
    uint32_t mSemaphoreIndex = 0;
    uint32_t mImageIndex = 0;
    bool mResized = false;
};

} // namespace tessera::gpu
