#include "StreamoutCrowdPasses.h"

#include "StreamoutCrowdBindings.h"

#include <algorithm>
#include <string>

namespace tessera::backends {

StreamoutCrowdPasses::StreamoutCrowdPasses(gpu::Device& device)
    : mDevice(device), mLayout(StreamoutCrowdBindings::layout(device)), mCull(device, mLayout), mBin(device, mLayout),
      mNearPass1(device, mLayout) {
    mXfb.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_TRANSFORM_FEEDBACK_PROPERTIES_EXT;
    VkPhysicalDeviceProperties2 properties{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &mXfb};
    vkGetPhysicalDeviceProperties2(device.physical(), &properties);
}

Status StreamoutCrowdPasses::checkCrowd(const GpuCrowd& crowd) const {
    const std::string prefix = "streamout: " + mDevice.features().deviceName + "'s transform feedback ";
    // Every count (survivors, list entries) comes from a stream query.
    if (!mXfb.transformFeedbackQueries)
        return fail(prefix, "cannot count the primitives a pass wrote (transformFeedbackQueries)");
    // The commands pass writes 32 bytes per vertex (two uvec4) to one buffer.
    constexpr uint32_t kCommandBytes = TS_CROWD_NEAR_COMMAND_WORDS * sizeof(uint32_t);
    if (mXfb.maxTransformFeedbackBufferDataStride < kCommandBytes ||
        mXfb.maxTransformFeedbackBufferDataSize < kCommandBytes ||
        mXfb.maxTransformFeedbackStreamDataSize < kCommandBytes)
        return fail(prefix, "cannot write ", std::to_string(kCommandBytes), " bytes per vertex to one buffer");
    // The largest range a crowd pass binds as one transform-feedback buffer.
    const VkDeviceSize largest = std::max({VkDeviceSize(crowd.maxInstances()) * sizeof(shader::CrowdListEntry),
                                           VkDeviceSize(crowd.nearSlots()) * crowd.nearStride() * 16,
                                           VkDeviceSize(crowd.creatures().size()) * crowd.nearSlots() * kCommandBytes});
    if (mXfb.maxTransformFeedbackBufferSize < largest)
        return fail(prefix, "binds at most ", std::to_string(mXfb.maxTransformFeedbackBufferSize),
                    " bytes per buffer; this crowd streams ", std::to_string(largest), " into one");
    return {};
}

Result<std::unique_ptr<StreamoutCrowdResources>> StreamoutCrowdPasses::createResources(GpuCrowd& crowd) const {
    if (Status supported = checkCrowd(crowd); !supported) return supported.error();
    return StreamoutCrowdResources::create(mDevice, crowd);
}

void StreamoutCrowdPasses::record(gpu::FrameContext& frame, GpuCrowd& crowd, StreamoutCrowdResources& resources,
                                  const gpu::UniformSlice& uniforms) {
    const StreamoutCrowdBindings bindings(crowd, resources, frame.slot(), uniforms);
    mCull.record(frame, crowd, resources, bindings);
    mBin.record(frame, crowd, resources, bindings);
    mNearPass1.record(frame, crowd, resources, bindings);
}

} // namespace tessera::backends
