#include "StreamoutFactorPass.h"

#include "common/TerrainBindings.h"
#include "tessera/gpu/Barriers.h"

#include "tessera/shaders/FrameUniforms.h"
#include "StreamoutRecording.h"
#include "tessera/shaders/TerrainUniforms.h"
#include "tessera/shaders/TessFactors.h"
#include "tessera/shaders/TessPattern.h"
#include "streamout_bindings.h"

#include "streamout_factors.vert.spv.h"

#include <string>

namespace tessera::backends {

namespace {

// What one invocation streams out (streamout_factors.vert).
constexpr uint32_t kStreams = 3;
constexpr uint32_t kTexelBytes = 16;
constexpr uint32_t kCommandBytes = TS_EMU_PIECES * sizeof(VkDrawIndirectCommand);
constexpr uint32_t kBytesPerVertex = 2 * kTexelBytes + kCommandBytes;

} // namespace

Status StreamoutFactorPass::checkDevice(const gpu::Device& device) {
    VkPhysicalDeviceTransformFeedbackPropertiesEXT xfb{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_TRANSFORM_FEEDBACK_PROPERTIES_EXT};
    VkPhysicalDeviceProperties2 properties{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &xfb};
    vkGetPhysicalDeviceProperties2(device.physical(), &properties);
    const std::string prefix = "streamout: " + device.features().deviceName + "'s transform feedback ";
    if (!xfb.transformFeedbackDraw) return fail(prefix, "cannot draw from a stream's counter (transformFeedbackDraw)");
    if (xfb.maxTransformFeedbackBuffers < kStreams)
        return fail(prefix, "binds ", std::to_string(xfb.maxTransformFeedbackBuffers),
                    " buffers; the factor pass writes ", std::to_string(kStreams));
    if (xfb.maxTransformFeedbackBufferDataStride < kCommandBytes ||
        xfb.maxTransformFeedbackStreamDataSize < kBytesPerVertex)
        return fail(prefix, "cannot write ", std::to_string(kBytesPerVertex), " bytes per vertex (",
                    std::to_string(kCommandBytes), " to one buffer)");
    return {};
}

StreamoutFactorPass::StreamoutFactorPass(gpu::Device& device) {
    const VkShaderStageFlags vertex = VK_SHADER_STAGE_VERTEX_BIT;
    mLayout = terrainLayout(device, vertex,
                            {{TS_BINDING_TESS, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, vertex},
                             {TS_BINDING_EDGE_ERROR, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, vertex},
                             {TS_BINDING_PATCH_ERROR, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, vertex},
                             {TS_BINDING_EMU_KEYS, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, vertex},
                             {SO_BINDING_CAGE, VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER, vertex}},
                            0, 0, "streamout.factors.layout");
    gpu::GraphicsPipelineDesc desc = streamout::streamOutPipelineDesc(
        "streamout.factors", mLayout, {{VK_SHADER_STAGE_VERTEX_BIT, streamout_factors_vert_spv}});
    // The survivors' stream, one point per surviving patch.
    desc.vertexBindings = {{0, sizeof(uint32_t), VK_VERTEX_INPUT_RATE_VERTEX}};
    desc.vertexAttributes = {{0, 0, VK_FORMAT_R32_UINT, 0}};
    mPipeline = gpu::Pipeline(device, desc);
}

void StreamoutFactorPass::record(const StreamoutPassInputs& in, const gpu::Buffer& keyTable, uint32_t visiblePatches) {
    gpu::PassScope pass(in.frame, "streamout.factors");
    VkCommandBuffer cmd = in.frame.cmd();
    const auto& fn = in.frame.device().fn();
    const StreamoutBuffers::Slot& buffers = in.buffers;
    const uint32_t slot = in.frame.slot();

    // Commands past the survivors must draw nothing; stream output writes
    // only the survivors' records. The draw issues only the visible patches'
    // commands (no more survive the cull), so only those are cleared.
    const VkDeviceSize drawn = VkDeviceSize(visiblePatches) * kCommandBytes;
    vkCmdFillBuffer(cmd, buffers.commands.handle(), 0, drawn, 0);
    gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                       VK_PIPELINE_STAGE_2_TRANSFORM_FEEDBACK_BIT_EXT,
                       VK_ACCESS_2_TRANSFORM_FEEDBACK_WRITE_BIT_EXT);

    streamout::beginStreamOut(cmd);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mPipeline.handle());
    const VkDescriptorBufferInfo tess = in.tessUniforms.descriptor();
    const VkDescriptorBufferInfo edgeErrors{in.terrain.edgeErrors(slot).handle(), 0, VK_WHOLE_SIZE};
    const VkDescriptorBufferInfo patchErrors{in.terrain.patchErrors(slot).handle(), 0, VK_WHOLE_SIZE};
    const VkDescriptorBufferInfo keys{keyTable.handle(), 0, VK_WHOLE_SIZE};
    const VkBufferView cage = buffers.cageView.handle();
    const VkWriteDescriptorSet writes[5] = {
        bufferWrite(TS_BINDING_TESS, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, &tess),
        bufferWrite(TS_BINDING_EDGE_ERROR, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, &edgeErrors),
        bufferWrite(TS_BINDING_PATCH_ERROR, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, &patchErrors),
        bufferWrite(TS_BINDING_EMU_KEYS, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, &keys),
        texelWrite(SO_BINDING_CAGE, &cage)};
    in.pushBindings(VK_PIPELINE_BIND_POINT_GRAPHICS, mLayout, writes);
    const VkBuffer survivors = buffers.survivors.handle();
    const VkDeviceSize zero = 0;
    vkCmdBindVertexBuffers(cmd, 0, 1, &survivors, &zero);

    // Streams 0 and 1 are the two halves of the records buffer (texel r and
    // capacity + r), stream 2 the commands.
    const VkDeviceSize half = VkDeviceSize(buffers.capacity) * kTexelBytes;
    const VkBuffer targets[kStreams] = {buffers.records.handle(), buffers.records.handle(), buffers.commands.handle()};
    const VkDeviceSize offsets[kStreams] = {0, half, 0};
    const VkDeviceSize sizes[kStreams] = {half, half, buffers.commands.size()};
    fn.cmdBindTransformFeedbackBuffers(cmd, 0, kStreams, targets, offsets, sizes);
    fn.cmdBeginTransformFeedback(cmd, 0, 0, nullptr, nullptr);
    // Draw-auto: the vertex count is the cull pass's counter / 4 bytes.
    fn.cmdDrawIndirectByteCount(cmd, 1, 0, buffers.counter.handle(), 0, 0, sizeof(uint32_t));
    fn.cmdEndTransformFeedback(cmd, 0, 0, nullptr, nullptr);
    streamout::endStreamOut(cmd);

    // The clear too: the commands past the survivors keep its zeros.
    gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_TRANSFORM_FEEDBACK_BIT_EXT | VK_PIPELINE_STAGE_2_TRANSFER_BIT,
                       VK_ACCESS_2_TRANSFORM_FEEDBACK_WRITE_BIT_EXT | VK_ACCESS_2_TRANSFER_WRITE_BIT,
                       VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT,
                       VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT | VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
}

} // namespace tessera::backends
