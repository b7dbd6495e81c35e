#include "common/TerrainSplatPass.h"

#include "tessera/gpu/RenderTarget.h"
#include "tessera/shaders/CraterProfile.h"

#include "fullscreen.vert.spv.h"
#include "terrain_splat.frag.spv.h"

namespace tessera::backends {

TerrainSplatPass::TerrainSplatPass(gpu::Device& device, const std::string& backendName) : mDevice(&device) {
    mLayout = gpu::PipelineLayout(device, {{0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT}},
                                  sizeof(shader::CraterSplatParams), VK_SHADER_STAGE_FRAGMENT_BIT,
                                  backendName + ".terrainSplat.layout");
    gpu::GraphicsPipelineDesc desc;
    desc.name = backendName + ".terrainSplat";
    desc.layout = &mLayout;
    desc.stages = {{VK_SHADER_STAGE_VERTEX_BIT, fullscreen_vert_spv}, {VK_SHADER_STAGE_FRAGMENT_BIT, terrain_splat_frag_spv}};
    desc.cullMode = VK_CULL_MODE_NONE;
    desc.depthTest = false;
    desc.depthWrite = false;
    desc.colorFormats = {VK_FORMAT_R16_UINT}; // the height map's integer alias view
    mPipeline = gpu::Pipeline(device, desc);
    mNearest = gpu::Sampler(device, VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, backendName + ".terrainSplat.sampler");
}

void TerrainSplatPass::record(gpu::FrameContext& frame, GpuTerrain& terrain, std::span<const terrain::CraterSplat> splats) {
    if (splats.empty()) return;
    gpu::PassScope pass(frame, "terrain.splat");
    for (const auto& splat : splats) splatOne(frame.cmd(), terrain, splat);
    // What a technique derived from the old heights is stale now.
    terrain.markHeightsChanged();
}

void TerrainSplatPass::splatOne(VkCommandBuffer cmd, GpuTerrain& terrain, const terrain::CraterSplat& splat) {
    const terrain::HeightField& field = terrain.source().field();
    const terrain::SampleRect rect = terrain::craterSamples(field, splat);
    if (rect.empty()) return;
    gpu::Image& heights = terrain.heightMap();
    gpu::Image& scratch = terrain.heightScratch();
    const VkImageAspectFlags color = VK_IMAGE_ASPECT_COLOR_BIT;
    const VkOffset3D origin{int32_t(rect.i0), int32_t(rect.j0), 0};
    const VkExtent2D extent{rect.i1 - rect.i0 + 1, rect.j1 - rect.j0 + 1};

    // Copy the region out first: a pass cannot sample the image it renders to.
    // Any stage of earlier passes may have sampled either image, hence ALL_COMMANDS.
    gpu::transitionImage(cmd, heights.handle(), color, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                         VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, 0,
                         VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
    gpu::transitionImage(cmd, scratch.handle(), color, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                         VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, 0, VK_PIPELINE_STAGE_2_COPY_BIT,
                         VK_ACCESS_2_TRANSFER_WRITE_BIT);
    VkImageCopy region{};
    region.srcSubresource = {color, 0, 0, 1};
    region.dstSubresource = {color, 0, 0, 1};
    region.srcOffset = origin;
    region.dstOffset = origin;
    region.extent = {extent.width, extent.height, 1};
    vkCmdCopyImage(cmd, heights.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, scratch.handle(),
                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    gpu::transitionImage(cmd, heights.handle(), color, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                         VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_COPY_BIT, 0,
                         VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
    gpu::transitionImage(cmd, scratch.handle(), color, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                         VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_COPY_BIT,
                         VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                         VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);

    // Fragment (i, j) is sample (i, j); the work stays in the crater's square.
    gpu::beginColorRendering(cmd, heights.aliasView(), heights.width(), heights.height(), {{origin.x, origin.y}, extent},
                             VK_ATTACHMENT_LOAD_OP_LOAD);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mPipeline.handle());
    VkDescriptorImageInfo source{mNearest.handle(), scratch.view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    write.dstBinding = 0;
    write.descriptorCount = 1;
    write.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    write.pImageInfo = &source;
    mDevice->fn().cmdPushDescriptorSet(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mLayout.handle(), 0, 1, &write);
    shader::CraterSplatParams params{};
    params.centerRadius = glm::vec4(splat.center, splat.radius, field.scale().horizontalSpacing);
    params.profile = glm::vec4(splat.profile.depth, splat.profile.rimHeight, splat.profile.rimAt, field.scale().heightScale);
    vkCmdPushConstants(cmd, mLayout.handle(), VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof params, &params);
    vkCmdDraw(cmd, 3, 1, 0, 0);
    vkCmdEndRendering(cmd);

    gpu::transitionImage(cmd, heights.handle(), color, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                         VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                         VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                         VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
}

} // namespace tessera::backends
