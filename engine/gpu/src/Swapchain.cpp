#include "tessera/gpu/Swapchain.h"

#include "tessera/gpu/Device.h"
#include "tessera/gpu/Image.h"
#include "tessera/gpu/Instance.h"
#include "tessera/gpu/RenderTarget.h"
#include "tessera/gpu/VulkanCheck.h"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include <algorithm>

namespace tessera::gpu {

bool Swapchain::initWindowSystem() {
    static const bool sOk = glfwInit() == GLFW_TRUE && glfwVulkanSupported() == GLFW_TRUE;
    return sOk;
}

Result<std::unique_ptr<Swapchain>> Swapchain::create(Instance& instance, Device& device, uint32_t width, uint32_t height,
                                                     const std::string& title) {
    if (!initWindowSystem())
        return failSetting("window", ": no display is available (GLFW could not initialise or has no Vulkan "
                                     "support); render headless (offscreen) instead");
    std::unique_ptr<Swapchain> swapchain(new Swapchain(instance, device));
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
    swapchain->mWindow = glfwCreateWindow(static_cast<int>(width), static_cast<int>(height), title.c_str(), nullptr, nullptr);
    if (!swapchain->mWindow) return failSetting("window", ": could not open a window");
    if (glfwCreateWindowSurface(instance.handle(), swapchain->mWindow, nullptr, &swapchain->mSurface) != VK_SUCCESS)
        return failSetting("window", ": could not create a Vulkan surface for the window");
    VkBool32 presentable = VK_FALSE;
    vkGetPhysicalDeviceSurfaceSupportKHR(device.physical(), device.queueFamily(), swapchain->mSurface, &presentable);
    if (!presentable) return failSetting("window", ": ", device.features().deviceName, " cannot present to this window");
    if (auto built = swapchain->build(); !built) return built.error();
    return swapchain;
}

Swapchain::~Swapchain() {
    mDevice.waitIdle();
    destroySwapchain();
    if (mSurface) vkDestroySurfaceKHR(mInstance.handle(), mSurface, nullptr);
    if (mWindow) glfwDestroyWindow(mWindow);
}

Status Swapchain::build() {
    VkSurfaceCapabilitiesKHR caps;
    vkGetPhysicalDeviceSurfaceCapabilitiesKHR(mDevice.physical(), mSurface, &caps);
    uint32_t formatCount = 0;
    vkGetPhysicalDeviceSurfaceFormatsKHR(mDevice.physical(), mSurface, &formatCount, nullptr);
    std::vector<VkSurfaceFormatKHR> formats(formatCount);
    vkGetPhysicalDeviceSurfaceFormatsKHR(mDevice.physical(), mSurface, &formatCount, formats.data());
    if (formats.empty()) return failSetting("window", ": the surface offers no formats");
    // The offscreen target is UNORM; pick a UNORM swapchain so the blit copies
    // values unchanged and windowed pixels equal headless screenshots.
    VkSurfaceFormatKHR chosen = formats[0];
    for (const auto& f : formats)
        if (f.format == VK_FORMAT_B8G8R8A8_UNORM || f.format == VK_FORMAT_R8G8B8A8_UNORM) chosen = f;
    mFormat = chosen.format;

    int w = 0, h = 0;
    glfwGetFramebufferSize(mWindow, &w, &h);
    mExtent = caps.currentExtent.width != UINT32_MAX
                  ? caps.currentExtent
                  : VkExtent2D{std::clamp(uint32_t(w), caps.minImageExtent.width, caps.maxImageExtent.width),
                               std::clamp(uint32_t(h), caps.minImageExtent.height, caps.maxImageExtent.height)};
    if (mExtent.width == 0 || mExtent.height == 0) return {}; // minimised: try again on resize

    VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
    info.surface = mSurface;
    info.minImageCount = std::max(caps.minImageCount, 3u);
    if (caps.maxImageCount) info.minImageCount = std::min(info.minImageCount, caps.maxImageCount);
    info.imageFormat = chosen.format;
    info.imageColorSpace = chosen.colorSpace;
    info.imageExtent = mExtent;
    info.imageArrayLayers = 1;
    info.imageUsage = VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
    info.preTransform = caps.currentTransform;
    info.compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
    info.presentMode = VK_PRESENT_MODE_FIFO_KHR;
    info.clipped = VK_TRUE;
    if (vkCreateSwapchainKHR(mDevice.handle(), &info, nullptr, &mSwapchain) != VK_SUCCESS)
        return failSetting("window", ": could not create the swapchain");
    mDevice.setName(VK_OBJECT_TYPE_SWAPCHAIN_KHR, mSwapchain, "window.swapchain");
    uint32_t count = 0;
    vkGetSwapchainImagesKHR(mDevice.handle(), mSwapchain, &count, nullptr);
    mImages.resize(count);
    vkGetSwapchainImagesKHR(mDevice.handle(), mSwapchain, &count, mImages.data());
    VkSemaphoreCreateInfo semInfo{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    for (uint32_t i = 0; i < count; ++i) {
        mDevice.setName(VK_OBJECT_TYPE_IMAGE, mImages[i], "window.swapchainImage" + std::to_string(i));
        VkSemaphore a, f;
        TESSERA_VK_CHECK(vkCreateSemaphore(mDevice.handle(), &semInfo, nullptr, &a));
        TESSERA_VK_CHECK(vkCreateSemaphore(mDevice.handle(), &semInfo, nullptr, &f));
        mDevice.setName(VK_OBJECT_TYPE_SEMAPHORE, a, "window.acquire" + std::to_string(i));
        mDevice.setName(VK_OBJECT_TYPE_SEMAPHORE, f, "window.renderFinished" + std::to_string(i));
        mAcquire.push_back(a);
        mFinished.push_back(f);
    }
    return {};
}

void Swapchain::destroySwapchain() {
    for (auto s : mAcquire) vkDestroySemaphore(mDevice.handle(), s, nullptr);
    for (auto s : mFinished) vkDestroySemaphore(mDevice.handle(), s, nullptr);
    mAcquire.clear();
    mFinished.clear();
    mImages.clear();
    if (mSwapchain) vkDestroySwapchainKHR(mDevice.handle(), mSwapchain, nullptr);
    mSwapchain = VK_NULL_HANDLE;
}

void Swapchain::recreate() {
    mDevice.waitIdle();
    destroySwapchain();
    (void)build();
    mResized = false;
}

bool Swapchain::shouldClose() const { return glfwWindowShouldClose(mWindow); }

bool Swapchain::pollEvents() {
    glfwPollEvents();
    int w = 0, h = 0;
    glfwGetFramebufferSize(mWindow, &w, &h);
    if (uint32_t(w) != mExtent.width || uint32_t(h) != mExtent.height) mResized = true;
    return mResized;
}

bool Swapchain::acquire(VkSemaphore& imageAvailable) {
    if (!mSwapchain || mResized) return false;
    mSemaphoreIndex = (mSemaphoreIndex + 1) % static_cast<uint32_t>(mAcquire.size());
    VkResult r = vkAcquireNextImageKHR(mDevice.handle(), mSwapchain, UINT64_MAX, mAcquire[mSemaphoreIndex],
                                       VK_NULL_HANDLE, &mImageIndex);
    if (r == VK_ERROR_OUT_OF_DATE_KHR) {
        mResized = true;
        return false;
    }
    if (r < 0) fatalVulkanError("vkAcquireNextImageKHR", r);
    imageAvailable = mAcquire[mSemaphoreIndex];
    return true;
}

VkSemaphore Swapchain::renderFinished() const { return mFinished[mImageIndex]; }

void Swapchain::recordPresentBlit(VkCommandBuffer cmd, RenderTarget& target) {
    VkImage dst = mImages[mImageIndex];
    transitionImage(cmd, target.color().handle(), VK_IMAGE_ASPECT_COLOR_BIT, RenderTarget::kColorLayoutAfterPasses,
                    VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                    VK_ACCESS_2_MEMORY_WRITE_BIT, VK_PIPELINE_STAGE_2_BLIT_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
    transitionImage(cmd, dst, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                    VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_BLIT_BIT,
                    VK_ACCESS_2_TRANSFER_WRITE_BIT);
    VkImageBlit region{};
    region.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.srcOffsets[1] = {int32_t(target.width()), int32_t(target.height()), 1};
    region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.dstOffsets[1] = {int32_t(mExtent.width), int32_t(mExtent.height), 1};
    vkCmdBlitImage(cmd, target.color().handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, dst,
                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region, VK_FILTER_LINEAR);
    transitionImage(cmd, dst, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                    VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, VK_PIPELINE_STAGE_2_BLIT_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                    VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE);
    transitionImage(cmd, target.color().handle(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                    RenderTarget::kColorLayoutAfterPasses, VK_PIPELINE_STAGE_2_BLIT_BIT, VK_ACCESS_2_NONE,
                    VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_READ_BIT);
}

bool Swapchain::present() {
    VkPresentInfoKHR info{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
    VkSemaphore wait = mFinished[mImageIndex];
    info.waitSemaphoreCount = 1;
    info.pWaitSemaphores = &wait;
    info.swapchainCount = 1;
    info.pSwapchains = &mSwapchain;
    info.pImageIndices = &mImageIndex;
    VkResult r = vkQueuePresentKHR(mDevice.queue(), &info);
    if (r == VK_ERROR_OUT_OF_DATE_KHR || r == VK_SUBOPTIMAL_KHR) {
        mResized = true;
        return false;
    }
    if (r < 0) fatalVulkanError("vkQueuePresentKHR", r);
    return true;
}

} // namespace tessera::gpu
