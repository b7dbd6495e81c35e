// engine/shaders/shadow_cascades.glsl against the CPU: the cascade a point
// selects (the shared tsShadowCascadeIndex, and scene::ShadowCascadeFit's
// twin), its coordinate in that cascade's map (the fit's matrices packed by
// scene::buildShadowCascadeUniforms, the normal offset and depth bias), and
// the sunlight it keeps from a gpu::ShadowMapArray where one cascade holds
// a caster at depth 0.5: shadowed behind it, lit in front of it, lit in the
// other cascades and beyond the last. Under the validation layer.
#include "GpuTestDevice.h"

#include "tessera/gpu/Barriers.h"
#include "tessera/gpu/Buffer.h"
#include "tessera/gpu/ComputePipeline.h"
#include "tessera/gpu/Pipeline.h"
#include "tessera/gpu/PipelineLayout.h"
#include "tessera/gpu/ShadowMapArray.h"
#include "tessera/scene/Camera.h"
#include "tessera/scene/ShadowCascadeFit.h"
#include "tessera/scene/ShadowCascadeUniforms.h"

#include "shadow_cascades_probe.comp.spv.h"
#include "shadow_map_depth.vert.spv.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace tessera;
using namespace tessera::test;

namespace {

constexpr uint32_t kMapSize = 64;
constexpr uint32_t kCasterLayer = 1;
constexpr float kCasterDepth = 0.5f;

/// Draws a caster over all of `layer` at `depth`; the other layers stay clear.
void drawCaster(gpu::Device& device, const gpu::ShadowMapArray& map, uint32_t layer, float depth) {
    gpu::PipelineLayout layout(device, {}, sizeof(glm::vec4), VK_SHADER_STAGE_VERTEX_BIT,
                               "shadowCascadesTest.depth.layout");
    gpu::GraphicsPipelineDesc desc;
    desc.name = "shadowCascadesTest.depth";
    desc.layout = &layout;
    desc.stages = {{VK_SHADER_STAGE_VERTEX_BIT, shadow_map_depth_vert_spv}};
    desc.cullMode = VK_CULL_MODE_NONE;
    desc.depthFormat = gpu::ShadowMapArray::kFormat;
    gpu::Pipeline pipeline(device, desc);
    device.submitImmediate(
        [&](VkCommandBuffer cmd) {
            map.beginWriting(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT);
            for (uint32_t l = 0; l < map.layers(); ++l) {
                map.beginLayer(cmd, l);
                if (l == layer) {
                    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline.handle());
                    const glm::vec4 push(depth, 0.0f, 0.0f, 0.0f);
                    vkCmdPushConstants(cmd, layout.handle(), VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof push, &push);
                    vkCmdDraw(cmd, 3, 1, 0, 0);
                }
                map.endLayer(cmd);
            }
            map.endWriting(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT);
        },
        "shadowCascadesTest.depth");
}

/// Runs shadow_cascades_probe.comp over `probes` (world xyz, view depth w).
std::vector<glm::vec4> runProbes(gpu::Device& device, const shader::ShadowCascadeUniforms& uniforms,
                                 const gpu::ShadowMapArray& map, const std::vector<glm::vec4>& probes) {
    const VkShaderStageFlags compute = VK_SHADER_STAGE_COMPUTE_BIT;
    gpu::PipelineLayout layout(device,
                               {{0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, compute},
                                {1, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, compute},
                                {2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, compute},
                                {3, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, compute}},
                               sizeof(glm::uvec4), compute, "shadowCascadesTest.probe.layout");
    gpu::ComputePipeline pipeline(device, layout, shadow_cascades_probe_comp_spv, "shadowCascadesTest.probe");
    gpu::Buffer ubo(device, sizeof uniforms, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, gpu::MemoryUsage::CpuToGpu,
                    "shadowCascadesTest.uniforms");
    gpu::Buffer in(device, probes.size() * sizeof(glm::vec4), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                   gpu::MemoryUsage::CpuToGpu, "shadowCascadesTest.probes");
    gpu::Buffer out(device, probes.size() * sizeof(glm::vec4), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                    gpu::MemoryUsage::GpuToCpu, "shadowCascadesTest.results");
    ubo.upload(std::span<const shader::ShadowCascadeUniforms>(&uniforms, 1));
    in.upload(std::span<const glm::vec4>(probes));
    device.submitImmediate(
        [&](VkCommandBuffer cmd) {
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.handle());
            const VkDescriptorBufferInfo buffers[3] = {
                {ubo.handle(), 0, VK_WHOLE_SIZE}, {in.handle(), 0, VK_WHOLE_SIZE}, {out.handle(), 0, VK_WHOLE_SIZE}};
            const VkDescriptorImageInfo image = map.descriptor();
            VkWriteDescriptorSet writes[4] = {};
            const VkDescriptorType types[4] = {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                                               VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER};
            for (uint32_t b = 0; b < 4; ++b) {
                writes[b].sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
                writes[b].dstBinding = b;
                writes[b].descriptorCount = 1;
                writes[b].descriptorType = types[b];
                if (b == 1) writes[b].pImageInfo = &image;
                else writes[b].pBufferInfo = &buffers[b == 0 ? 0 : b - 1];
            }
            device.fn().cmdPushDescriptorSet(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout.handle(), 0, 4, writes);
            const glm::uvec4 count(uint32_t(probes.size()), 0, 0, 0);
            vkCmdPushConstants(cmd, layout.handle(), compute, 0, sizeof count, &count);
            vkCmdDispatch(cmd, (uint32_t(probes.size()) + 15) / 16, 1, 1);
            gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                               VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
        },
        "shadowCascadesTest.probe");
    const auto* mapped = static_cast<const glm::vec4*>(out.mapped());
    return std::vector<glm::vec4>(mapped, mapped + probes.size());
}

} // namespace

TEST(ShadowCascadesGlsl, SelectionCoordinatesAndSunlightMatchTheCpu) {
    std::string why;
    gpu::Device* device = GpuTestDevice::get(why);
    if (!device) GTEST_SKIP() << "no Vulkan device: " << why;
    const uint64_t messagesBefore = GpuTestDevice::validationMessages();

    scene::Camera camera;
    camera.setPose({{1800.0f, 420.0f, 6800.0f}, glm::radians(-30.0f), glm::radians(-16.0f)});
    const glm::vec3 sun = glm::normalize(glm::vec3(0.6f, 0.5f, -0.45f));
    scene::ShadowCascadeFit::Settings settings;
    settings.resolution = kMapSize;
    const std::vector<scene::ShadowCascade> cascades = scene::ShadowCascadeFit(settings).fit(camera, sun);
    const shader::ShadowCascadeUniforms uniforms = scene::buildShadowCascadeUniforms(cascades, kMapSize);

    // Points on the view axis in every cascade and beyond the last, and the
    // same points moved towards the sun (nearer depth, same texel).
    std::vector<glm::vec4> probes;
    for (float depth : {1.0f, 4.0f, 9.0f, 20.0f, 35.0f, 60.0f, 120.0f, 250.0f, 299.0f, 320.0f}) {
        const glm::vec3 onAxis = camera.position() + camera.forward() * depth;
        for (float towardsSun : {0.0f, 40.0f, 90.0f, 140.0f})
            probes.emplace_back(onAxis + sun * towardsSun, depth);
    }
    {
        gpu::ShadowMapArray map(*device, kMapSize, uint32_t(cascades.size()), "shadowCascadesTest.map");
        drawCaster(*device, map, kCasterLayer, kCasterDepth);
        const std::vector<glm::vec4> results = runProbes(*device, uniforms, map, probes);

        int shadowed = 0, litInCasterLayer = 0;
        for (size_t i = 0; i < probes.size(); ++i) {
            const float viewDepth = probes[i].w;
            const size_t cpuIndex = scene::ShadowCascadeFit::cascadeIndex(cascades, viewDepth);
            ASSERT_EQ(shader::tsShadowCascadeIndex(uniforms.farDistances, uint32_t(cascades.size()), viewDepth),
                      cpuIndex);
            const uint32_t gpuIndex = uint32_t(std::floor(results[i].w));
            const float lit = 2.0f * (results[i].w - float(gpuIndex));
            ASSERT_EQ(gpuIndex, cpuIndex) << "probe " << i;
            if (cpuIndex >= cascades.size()) {
                EXPECT_EQ(lit, 1.0f) << "beyond the last cascade: lit";
                continue;
            }
            const scene::ShadowCascade& c = cascades[cpuIndex];
            const glm::vec3 offset = glm::vec3(probes[i]) + glm::vec3(0, 1, 0) * (c.texelSize * 1.5f);
            const glm::vec4 clip = c.viewProjection * glm::vec4(offset, 1.0f);
            const glm::vec3 expected(glm::vec2(clip) * 0.5f + 0.5f, clip.z - 0.05f / c.depthRange);
            EXPECT_NEAR(results[i].x, expected.x, 1e-4f) << "probe " << i;
            EXPECT_NEAR(results[i].y, expected.y, 1e-4f) << "probe " << i;
            EXPECT_NEAR(results[i].z, expected.z, 1e-4f) << "probe " << i;
            if (cpuIndex != kCasterLayer) {
                EXPECT_EQ(lit, 1.0f) << "probe " << i << ": no caster in cascade " << cpuIndex;
            } else if (std::abs(expected.z - kCasterDepth) > 0.02f) {
                const float want = expected.z > kCasterDepth ? 0.0f : 1.0f;
                EXPECT_NEAR(lit, want, 1e-3f) << "probe " << i << " at depth " << expected.z;
                (want == 0.0f ? shadowed : litInCasterLayer)++;
            }
        }
        EXPECT_GT(shadowed, 0) << "no probe behind the caster";
        EXPECT_GT(litInCasterLayer, 0) << "no probe in front of the caster";
        device->waitIdle();
    }
    EXPECT_EQ(GpuTestDevice::validationMessages(), messagesBefore) << "validation messages (see stderr)";
}
