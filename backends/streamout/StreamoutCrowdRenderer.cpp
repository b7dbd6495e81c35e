#include "StreamoutCrowdRenderer.h"

#include "common/CrowdDescriptors.h"
#include "StreamoutCrowdBindings.h"

#include "character.frag_crowd_texels.spv.h"
#include "crowd_mesh.vert_texels.spv.h"

#include <algorithm>
#include <string>

namespace tessera::backends {

StreamoutCrowdRenderer::StreamoutCrowdRenderer(gpu::Device& device, VkFormat colorFormat, VkFormat depthFormat)
    : mDevice(device), mCrowds(device), mLayout(StreamoutCrowdBindings::layout(device)), mCull(device, mLayout),
      mBin(device, mLayout), mNearPass1(device, mLayout), mNear(device, colorFormat, depthFormat, "streamout"),
      mMesh(device, CrowdDescriptors::Mode::Texels, crowd_mesh_vert_texels_spv, character_frag_crowd_texels_spv,
            colorFormat, depthFormat, "streamout.crowd.mesh") {
    mXfb.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_TRANSFORM_FEEDBACK_PROPERTIES_EXT;
    VkPhysicalDeviceProperties2 properties{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &mXfb};
    vkGetPhysicalDeviceProperties2(device.physical(), &properties);
}

Status StreamoutCrowdRenderer::checkCrowd(const GpuCrowd& crowd) const {
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

Result<backend::CrowdHandle>
StreamoutCrowdRenderer::create(const backend::CrowdDesc& desc,
                               const std::function<GpuCharacter*(backend::CharacterHandle)>& find) {
    auto handle = mCrowds.create(desc, find, VK_BUFFER_USAGE_TRANSFORM_FEEDBACK_BUFFER_BIT_EXT);
    if (!handle) return handle;
    GpuCrowd& crowd = *mCrowds.find(handle.value());
    Status supported = checkCrowd(crowd);
    auto resources = supported ? StreamoutCrowdResources::create(mDevice, crowd)
                               : Result<std::unique_ptr<StreamoutCrowdResources>>(supported.error());
    if (!resources) {
        mCrowds.destroy(handle.value());
        return resources.error();
    }
    if (mResources.size() <= handle.value().id) mResources.resize(handle.value().id + 1);
    mResources[handle.value().id] = std::move(resources.value());
    return handle;
}

void StreamoutCrowdRenderer::destroy(backend::CrowdHandle handle) {
    if (!find(handle)) return;
    mCrowds.destroy(handle);
    // Frames in flight may still use the resources: free them once retired.
    StreamoutCrowdResources* released = mResources[handle.id].release();
    mDevice.deferDestroy([released] { delete released; });
}

void StreamoutCrowdRenderer::recordPasses(gpu::FrameContext& frame, backend::CrowdHandle handle,
                                          const gpu::UniformSlice& uniforms) {
    GpuCrowd& crowd = *find(handle);
    StreamoutCrowdResources& resources = *mResources[handle.id];
    const StreamoutCrowdBindings bindings(crowd, resources, frame.slot(), uniforms);
    mCull.record(frame, crowd, resources, bindings);
    mBin.record(frame, crowd, resources, bindings);
    mNearPass1.record(frame, crowd, resources, bindings);
}

void StreamoutCrowdRenderer::recordDraws(gpu::FrameContext& frame, GpuCrowd& crowd,
                                         const gpu::UniformSlice& frameUniforms, const gpu::UniformSlice& uniforms) {
    CrowdDescriptors descriptors(CrowdDescriptors::Mode::Texels, crowd, frame.slot(), frameUniforms, uniforms);
    mNear.record(frame, crowd, descriptors);
    mMesh.record(frame, crowd, descriptors);
}

uint64_t StreamoutCrowdRenderer::bytes(backend::CrowdHandle handle) {
    GpuCrowd* crowd = find(handle);
    return crowd ? crowd->bytes() + mResources[handle.id]->bytes() : 0;
}

} // namespace tessera::backends
