#include "common/TerrainResolvePass.h"

#include "common/CommandHelpers.h"
#include "common/TerrainBindings.h"
#include "tessera/gpu/Device.h"
#include "tessera/gpu/RenderTarget.h"
#include "tessera/shaders/FrameUniforms.h"
#include "tessera/shaders/TerrainUniforms.h"

#include "sky.vert.spv.h"
#include "terrain_resolve.comp.spv.h"
#include "terrain_resolve.frag.spv.h"

namespace tessera::backends {

namespace {
constexpr uint32_t kGroupSize = 8; // terrain_resolve.comp's local size
constexpr VkPipelineStageFlags2 kColorOutput = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;
constexpr VkAccessFlags2 kColorAccess = VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT;
} // namespace

TerrainResolvePass::TerrainResolvePass(gpu::Device& device, const std::string& backendName, Mode mode,
                                       VkFormat colorFormat, VkFormat depthFormat)
    : mDevice(&device), mMode(mode) {
    const bool compute = mode == Mode::Compute;
    const VkShaderStageFlags stage = compute ? VK_SHADER_STAGE_COMPUTE_BIT : VK_SHADER_STAGE_FRAGMENT_BIT;
    std::vector<gpu::BindingDesc> bindings = terrainBindings(stage);
    // The fragment resolve's vertex shader (sky.vert) reads the frame too.
    if (!compute) bindings.front().stages |= VK_SHADER_STAGE_VERTEX_BIT;
    if (compute)
        bindings.push_back({TS_BINDING_RESOLVE_TARGET, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, stage});
    else
        bindings.push_back({TS_BINDING_RESOLVE_SOURCE, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, stage});
    mLayout = gpu::PipelineLayout(device, bindings, 0, 0, backendName + ".terrainResolve.layout");
    if (compute) {
        mComputePipeline = gpu::ComputePipeline(device, mLayout, terrain_resolve_comp_spv, backendName + ".terrainResolve");
        return;
    }
    // The fragment resolve reads its copy with texelFetch; the sampler only has to exist.
    mSourceSampler = gpu::Sampler(device, VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE,
                                  backendName + ".terrainResolve.sourceSampler");
    gpu::GraphicsPipelineDesc desc;
    desc.name = backendName + ".terrainResolve";
    desc.layout = &mLayout;
    // The sky's triangle lies at the far plane (depth 1); GREATER passes
    // where the main pass drew anything, so uncovered pixels are never shaded.
    desc.stages = {{VK_SHADER_STAGE_VERTEX_BIT, sky_vert_spv}, {VK_SHADER_STAGE_FRAGMENT_BIT, terrain_resolve_frag_spv}};
    desc.cullMode = VK_CULL_MODE_NONE;
    desc.depthTest = true;
    desc.depthWrite = false;
    desc.depthCompare = VK_COMPARE_OP_GREATER;
    desc.colorFormats = {colorFormat};
    desc.depthFormat = depthFormat;
    mPipeline = gpu::Pipeline(device, desc);
}

void TerrainResolvePass::record(gpu::FrameContext& frame, const PushTerrainBindings& pushTerrain) {
    gpu::PassScope pass(frame, "terrain.resolve");
    if (mMode == Mode::Compute)
        recordCompute(frame, pushTerrain);
    else
        recordFragment(frame, pushTerrain);
}

void TerrainResolvePass::recordCompute(gpu::FrameContext& frame, const PushTerrainBindings& pushTerrain) {
    VkCommandBuffer cmd = frame.cmd();
    gpu::RenderTarget& target = frame.target();
    gpu::Image& color = target.color();
    const VkPipelineStageFlags2 compute = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
    gpu::transitionImage(cmd, color.handle(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                         VK_IMAGE_LAYOUT_GENERAL, kColorOutput, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, compute,
                         VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, mComputePipeline.handle());
    const VkDescriptorImageInfo colorInfo{VK_NULL_HANDLE, color.view(), VK_IMAGE_LAYOUT_GENERAL};
    VkWriteDescriptorSet storage = imageWrite(TS_BINDING_RESOLVE_TARGET, &colorInfo);
    storage.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
    pushTerrain(VK_PIPELINE_BIND_POINT_COMPUTE, mLayout, {&storage, 1});
    vkCmdDispatch(cmd, (target.width() + kGroupSize - 1) / kGroupSize, (target.height() + kGroupSize - 1) / kGroupSize,
                  1);
    gpu::transitionImage(cmd, color.handle(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_GENERAL,
                         VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, compute, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                         kColorOutput, kColorAccess);
}

void TerrainResolvePass::recordFragment(gpu::FrameContext& frame, const PushTerrainBindings& pushTerrain) {
    VkCommandBuffer cmd = frame.cmd();
    gpu::RenderTarget& target = frame.target();
    gpu::Image& color = target.color();
    if (!mSource || mSource->width() != target.width() || mSource->height() != target.height()) {
        // A frame in flight may still read the old copy.
        if (mSource) mDevice->deferRelease(std::move(mSource));
        gpu::ImageDesc desc;
        desc.width = target.width();
        desc.height = target.height();
        desc.format = gpu::RenderTarget::kColorFormat;
        desc.usage = VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
        desc.name = "terrainResolve.source";
        mSource = std::make_unique<gpu::Image>(*mDevice, desc);
    }
    // A pass cannot sample the image it renders to: the D3D9 way, copy the
    // main pass's result to a texture and read that.
    const VkPipelineStageFlags2 copy = VK_PIPELINE_STAGE_2_COPY_BIT;
    const VkPipelineStageFlags2 fragment = VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
    const VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT;
    gpu::transitionImage(cmd, color.handle(), aspect, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                         VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, kColorOutput, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, copy,
                         VK_ACCESS_2_TRANSFER_READ_BIT);
    // The previous frame's resolve may still read the copy.
    gpu::transitionImage(cmd, mSource->handle(), aspect, VK_IMAGE_LAYOUT_UNDEFINED,
                         VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, fragment, 0, copy, VK_ACCESS_2_TRANSFER_WRITE_BIT);
    VkImageCopy region{};
    region.srcSubresource = {aspect, 0, 0, 1};
    region.dstSubresource = {aspect, 0, 0, 1};
    region.extent = {target.width(), target.height(), 1};
    vkCmdCopyImage(cmd, color.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, mSource->handle(),
                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    gpu::transitionImage(cmd, mSource->handle(), aspect, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                         VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, copy, VK_ACCESS_2_TRANSFER_WRITE_BIT, fragment,
                         VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
    gpu::transitionImage(cmd, color.handle(), aspect, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                         VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, copy, 0, kColorOutput, kColorAccess);

    target.resumeRendering(cmd);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mPipeline.handle());
    const VkDescriptorImageInfo sourceInfo{mSourceSampler.handle(), mSource->view(),
                                           VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    const VkWriteDescriptorSet source = imageWrite(TS_BINDING_RESOLVE_SOURCE, &sourceInfo);
    pushTerrain(VK_PIPELINE_BIND_POINT_GRAPHICS, mLayout, {&source, 1});
    vkCmdDraw(cmd, 3, 1, 0, 0);
    target.endRendering(cmd);
}

} // namespace tessera::backends
