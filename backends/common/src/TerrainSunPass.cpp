#include "common/TerrainSunPass.h"

#include "common/CommandHelpers.h"
#include "tessera/gpu/RenderTarget.h"

#include "tessera/shaders/TerrainUniforms.h"

#include "fullscreen.vert.spv.h"
#include "terrain_sun.frag.spv.h"

#include <cmath>

namespace tessera::backends {

namespace {
// The march: 40 steps from one height sample out to ~2.5 km, each 18% longer
// than the last (near steps find the small crests, far ones the mountains).
constexpr float kSteps = 40.0f;
constexpr float kGrowth = 1.18f;
// Half the angular width of the shadow's soft edge: wider than the real sun
// (0.27 degrees) so the map's texels do not show as stairs.
constexpr float kPenumbraRadians = 0.035f;
} // namespace

TerrainSunPass::TerrainSunPass(gpu::Device& device, const std::string& backendName) : mDevice(&device) {
    const VkShaderStageFlags fragment = VK_SHADER_STAGE_FRAGMENT_BIT;
    mLayout = gpu::PipelineLayout(device,
                                  {{TS_BINDING_TERRAIN, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, fragment},
                                   {TS_BINDING_HEIGHTMAP, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, fragment}},
                                  sizeof(shader::TerrainSunParams), fragment, backendName + ".terrainSun.layout");
    gpu::GraphicsPipelineDesc desc;
    desc.name = backendName + ".terrainSun";
    desc.layout = &mLayout;
    desc.stages = {{VK_SHADER_STAGE_VERTEX_BIT, fullscreen_vert_spv}, {VK_SHADER_STAGE_FRAGMENT_BIT, terrain_sun_frag_spv}};
    desc.cullMode = VK_CULL_MODE_NONE;
    desc.depthTest = false;
    desc.depthWrite = false;
    desc.colorFormats = {VK_FORMAT_R8_UNORM};
    mPipeline = gpu::Pipeline(device, desc);
}

/// The texels of `terrain`'s map whose march towards `sun` crosses the world
/// XZ rectangle `region` (min x, min z, max x, max z): the rectangle swept
/// back from the sun over the march's reach, plus two texels for the
/// bilinear height samples; empty (zero extent) when it misses the map.
VkRect2D TerrainSunPass::affectedTexels(GpuTerrain& terrain, const glm::vec4& region, const glm::vec3& sun) {
    const shader::TerrainUniforms& u = terrain.uniforms();
    const float spacing = u.worldSize.w;
    glm::vec2 lo(region.x, region.y), hi(region.z, region.w);
    const float horizontal = glm::length(glm::vec2(sun.x, sun.z));
    if (horizontal > 1e-4f) {
        const glm::vec2 back = -glm::vec2(sun.x, sun.z) / horizontal * (spacing * std::pow(kGrowth, kSteps - 1.0f));
        lo = glm::min(lo, lo + back);
        hi = glm::max(hi, hi + back);
    }
    gpu::Image& map = terrain.sunVisibility();
    const glm::vec2 size(float(map.width()), float(map.height()));
    // World XZ to texels: terrainTexcoord() times the map's size.
    auto toTexel = [&](glm::vec2 xz) { return (xz / spacing + 0.5f) * glm::vec2(u.heightTexel) * size; };
    const glm::vec2 a = glm::clamp(glm::floor(toTexel(lo)) - 2.0f, glm::vec2(0.0f), size);
    const glm::vec2 b = glm::clamp(glm::ceil(toTexel(hi)) + 2.0f, glm::vec2(0.0f), size);
    VkRect2D rect{{int32_t(a.x), int32_t(a.y)}, {uint32_t(b.x - a.x), uint32_t(b.y - a.y)}};
    return rect;
}

void TerrainSunPass::update(gpu::FrameContext& frame, GpuTerrain& terrain, const glm::vec3& sunDirection) {
    const bool whole = terrain.sunVisibilityStale(sunDirection);
    if (!whole && !terrain.sunVisibilityDirty()) return;
    gpu::Image& map = terrain.sunVisibility();
    VkRect2D area{{0, 0}, {map.width(), map.height()}};
    // After craters, only the texels whose horizon they can change: a full
    // map is hundreds of milliseconds on lavapipe, a crater's share a few.
    if (!whole) area = affectedTexels(terrain, *terrain.sunVisibilityDirty(), sunDirection);
    if (area.extent.width == 0 || area.extent.height == 0) {
        terrain.markSunVisibility(sunDirection);
        return;
    }
    gpu::PassScope pass(frame, "terrain.sun");
    VkCommandBuffer cmd = frame.cmd();
    const VkImageAspectFlags color = VK_IMAGE_ASPECT_COLOR_BIT;
    // A whole redraw rewrites every texel, so the old contents go
    // (UNDEFINED); a partial one keeps the rest. Earlier terrain draws may
    // still be sampling it, hence the fragment stage.
    gpu::transitionImage(cmd, map.handle(), color,
                         whole ? VK_IMAGE_LAYOUT_UNDEFINED : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                         VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, 0,
                         VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                         VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);

    gpu::beginColorRendering(cmd, map.view(), map.width(), map.height(), area,
                             whole ? VK_ATTACHMENT_LOAD_OP_DONT_CARE : VK_ATTACHMENT_LOAD_OP_LOAD);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mPipeline.handle());

    VkDescriptorBufferInfo terrainInfo{terrain.uniformBuffer().handle(), 0, VK_WHOLE_SIZE};
    VkDescriptorImageInfo heightInfo{terrain.sampler().handle(), terrain.heightMap().view(),
                                     VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    const VkWriteDescriptorSet writes[2] = {bufferWrite(TS_BINDING_TERRAIN, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, &terrainInfo),
                                            imageWrite(TS_BINDING_HEIGHTMAP, &heightInfo)};
    mDevice->fn().cmdPushDescriptorSet(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mLayout.handle(), 0, 2, writes);

    shader::TerrainSunParams params{};
    const float spacing = terrain.uniforms().worldSize.w;
    params.sun = glm::vec4(sunDirection, kPenumbraRadians);
    // Half a metre of bias keeps a texel from shadowing itself through the
    // bilinear height between samples.
    params.march = glm::vec4(kSteps, spacing, kGrowth, 0.5f);
    params.map = glm::vec4(1.0f / float(map.width()), 1.0f / float(map.height()), 0.0f, 0.0f);
    vkCmdPushConstants(cmd, mLayout.handle(), VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof params, &params);
    vkCmdDraw(cmd, 3, 1, 0, 0);
    vkCmdEndRendering(cmd);

    gpu::transitionImage(cmd, map.handle(), color, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                         VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                         VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                         VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
    terrain.markSunVisibility(sunDirection);
}

} // namespace tessera::backends
