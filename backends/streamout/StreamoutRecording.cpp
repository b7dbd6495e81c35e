#include "StreamoutRecording.h"

namespace tessera::backends::streamout {

void beginStreamOut(VkCommandBuffer cmd) {
    VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
    rendering.renderArea = {{0, 0}, {1, 1}};
    rendering.layerCount = 1;
    vkCmdBeginRendering(cmd, &rendering);
    // The pipelines' viewport and scissor are dynamic; they must be set even
    // though rasterizer discard never uses them.
    const VkViewport viewport{0.0f, 0.0f, 1.0f, 1.0f, 0.0f, 1.0f};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &rendering.renderArea);
}

void endStreamOut(VkCommandBuffer cmd) {
    vkCmdEndRendering(cmd);
}

} // namespace tessera::backends::streamout
