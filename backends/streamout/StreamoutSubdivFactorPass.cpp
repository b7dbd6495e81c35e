#include "StreamoutSubdivFactorPass.h"

#include "common/CommandHelpers.h"
#include "StreamoutRecording.h"
#include "StreamoutSubdivBuffers.h"
#include "tessera/shaders/TessPattern.h"
#include "tessera/gpu/Barriers.h"

#include "streamout_subdiv_factors.vert.spv.h"

#include <cassert>
#include <vector>

namespace tessera::backends {

namespace {
constexpr uint32_t kStreams = 3;
constexpr VkDeviceSize kTexelBytes = 16;
} // namespace

StreamoutSubdivFactorPass::StreamoutSubdivFactorPass(gpu::Device& device) {
    const VkShaderStageFlags vertex = VK_SHADER_STAGE_VERTEX_BIT;
    std::vector<gpu::BindingDesc> bindings = GpuSubdiv::levelBindings(vertex);
    bindings.push_back({TS_BINDING_EMU_KEYS, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, vertex});
    mLayout = gpu::PipelineLayout(device, bindings, 0, 0, "streamout.subdivFactors.layout");
    gpu::GraphicsPipelineDesc desc = streamout::streamOutPipelineDesc(
        "streamout.subdivFactors", mLayout, {{VK_SHADER_STAGE_VERTEX_BIT, streamout_subdiv_factors_vert_spv}});
    // No vertex stream: the vertex index is the domain.
    mPipeline = gpu::Pipeline(device, desc);
}

EmulatedDrawSource StreamoutSubdivFactorPass::record(gpu::FrameContext& frame, GpuSubdiv& surface,
                                                     const gpu::UniformSlice& uniforms, const gpu::Buffer& keyTable) {
    auto* buffers = static_cast<StreamoutSubdivBuffers*>(surface.extension());
    assert(buffers && "StreamoutBackend attaches the buffers at createSubdiv");
    gpu::PassScope pass(frame, "subdiv.factors");
    VkCommandBuffer cmd = frame.cmd();
    const auto& fn = frame.device().fn();
    // The previous draw of this surface may still read the records and
    // commands (write after read).
    gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT,
                       VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_TRANSFORM_FEEDBACK_BIT_EXT,
                       VK_ACCESS_2_TRANSFORM_FEEDBACK_WRITE_BIT_EXT);
    streamout::beginStreamOut(cmd);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mPipeline.handle());
    std::vector<VkWriteDescriptorSet> writes = surface.levelWrites(uniforms);
    const VkDescriptorBufferInfo keys{keyTable.handle(), 0, VK_WHOLE_SIZE};
    writes.push_back(bufferWrite(TS_BINDING_EMU_KEYS, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, &keys));
    fn.cmdPushDescriptorSet(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mLayout.handle(), 0, uint32_t(writes.size()),
                            writes.data());
    // Streams 0 and 1 are the two halves of the records buffer (texel r and
    // capacity + r), stream 2 the commands.
    const VkDeviceSize half = VkDeviceSize(buffers->capacity) * kTexelBytes;
    const VkBuffer targets[kStreams] = {buffers->records.handle(), buffers->records.handle(),
                                        buffers->commands.handle()};
    const VkDeviceSize offsets[kStreams] = {0, half, 0};
    const VkDeviceSize sizes[kStreams] = {half, half, buffers->commands.size()};
    fn.cmdBindTransformFeedbackBuffers(cmd, 0, kStreams, targets, offsets, sizes);
    fn.cmdBeginTransformFeedback(cmd, 0, 0, nullptr, nullptr);
    vkCmdDraw(cmd, surface.domainCount(), 1, 0, 0);
    fn.cmdEndTransformFeedback(cmd, 0, 0, nullptr, nullptr);
    streamout::endStreamOut(cmd);
    gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_TRANSFORM_FEEDBACK_BIT_EXT, VK_ACCESS_2_TRANSFORM_FEEDBACK_WRITE_BIT_EXT,
                       VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT,
                       VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT | VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
    return buffers->source();
}

} // namespace tessera::backends
