#include "common/CrowdImpostorPass.h"

#include "tessera/gpu/Device.h"

namespace tessera::backends {

std::span<const uint32_t> crowdImpostorFragment(const gpu::Device& device, std::span<const uint32_t> blended,
                                                std::span<const uint32_t> nearest) {
    return device.features().isCpu ? nearest : blended;
}

// The list's entries are the only stream; the card's corners are its
// indices. No face is culled: a card faces the baked view nearest the eye,
// and where the eye is below the creature's horizon (the views are the
// upper hemisphere's) it may be seen from behind, which should still show it.
CrowdImpostorPass::CrowdImpostorPass(gpu::Device& device, CrowdDescriptors::Mode mode,
                                     std::span<const uint32_t> vertex, std::span<const uint32_t> fragment,
                                     VkFormat colorFormat, VkFormat depthFormat, const std::string& name)
    : mPipeline(device, mode, vertex, fragment,
                {sizeof(shader::CrowdListEntry), VK_VERTEX_INPUT_RATE_INSTANCE, VK_FORMAT_R32G32B32A32_UINT},
                VK_FRONT_FACE_COUNTER_CLOCKWISE, VK_CULL_MODE_NONE, colorFormat, depthFormat, name) {}

void CrowdImpostorPass::record(gpu::FrameContext& frame, GpuCrowd& crowd, CrowdDescriptors& descriptors) {
    mPipeline.record(frame, "crowd.impostor", crowd, descriptors, crowd.lists().handle(), crowd.indices().handle(),
                     [&](VkCommandBuffer cmd, uint32_t c) {
                         const VkDeviceSize offset = VkDeviceSize(TS_LOD_IMPOSTOR * TS_CROWD_MAX_CHARACTERS + c) *
                                                     TS_CROWD_ARG_DRAW_WORDS * sizeof(uint32_t);
                         vkCmdDrawIndexedIndirect(cmd, crowd.args().handle(), offset, 1, 0);
                     });
}

} // namespace tessera::backends
