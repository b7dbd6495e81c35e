#pragma once
/// @file RenderTarget.h
/// The offscreen color and depth images a frame renders into.
///
/// Every mode renders offscreen first: headless runs read the color image
/// back for screenshots and tests, windowed runs blit it to the swapchain.
/// Backends therefore never see a swapchain, and the two modes produce the
/// same pixels.

#include "tessera/gpu/Image.h"

#include <cstdint>
#include <vector>

namespace tessera::gpu {

class Device;

class RenderTarget {
public:
    static constexpr VkFormat kColorFormat = VK_FORMAT_R8G8B8A8_UNORM;
    static constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;

    RenderTarget(Device& device, uint32_t width, uint32_t height);

    uint32_t width() const { return mColor.width(); }
    uint32_t height() const { return mColor.height(); }
    Image& color() { return mColor; }
    Image& depth() { return mDepth; }

    /// Layout the color image is left in at the end of each frame's passes;
    /// the host transitions from here for readback or presentation.
    static constexpr VkImageLayout kColorLayoutAfterPasses = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;

    /// Transitions both images from UNDEFINED and begins dynamic rendering
    /// into them, clearing to `clear` (color) and 1.0 (depth).
    void beginRendering(VkCommandBuffer cmd, const float clear[4]);
    /// Reopens rendering after an endRendering in the same frame, keeping what
    /// was drawn (load, not clear), after a barrier on the earlier writes.
    /// Lets a backend run off-target passes (compute, stream-out, R2VB) between
    /// draws into the frame.
    void resumeRendering(VkCommandBuffer cmd);
    void endRendering(VkCommandBuffer cmd);

private:
    void begin(VkCommandBuffer cmd, const float clear[4], VkAttachmentLoadOp load);

    Image mColor;
    Image mDepth;
};

/// Begins dynamic rendering into one colour image (`view`, `width` x
/// `height`, COLOR_ATTACHMENT_OPTIMAL, no depth) for the passes that render
/// into a texture (splats, the sun-visibility map, the characters' shadow
/// mask). The viewport covers the whole image, so fragment (i, j) is texel
/// (i, j); the render area and the scissor are `area`, so the work stays
/// there. `load` is the colour's load op (CLEAR clears to zero). End with
/// vkCmdEndRendering.
void beginColorRendering(VkCommandBuffer cmd, VkImageView view, uint32_t width, uint32_t height, const VkRect2D& area,
                         VkAttachmentLoadOp load);

} // namespace tessera::gpu
