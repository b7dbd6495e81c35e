// gpu::ShadowMapArray, the cascaded shadow map's depth layers: a depth-only
// pass writes one layer, the others are cleared, and a compute shader reads
// every layer through the comparison sampler (sampler2DArrayShadow). Lit
// where the reference is at or in front of the stored depth, shadowed
// behind it, lit outside the map (the border) and in a layer nothing was
// drawn into; right after creation everything reads lit. Under the
// validation layer: any message fails.
#include "GpuTestDevice.h"

#include "tessera/gpu/Barriers.h"
#include "tessera/gpu/Buffer.h"
#include "tessera/gpu/ComputePipeline.h"
#include "tessera/gpu/Pipeline.h"
#include "tessera/gpu/PipelineLayout.h"
#include "tessera/gpu/ShadowMapArray.h"

#include "shadow_map_depth.vert.spv.h"
#include "shadow_map_probe.comp.spv.h"

#include <gtest/gtest.h>

#include <glm/glm.hpp>
#include <vector>

using namespace tessera;
using namespace tessera::test;

namespace {

constexpr uint32_t kSize = 32;
constexpr uint32_t kLayers = 3;
constexpr uint32_t kDrawnLayer = 1;
constexpr float kDrawnDepth = 0.5f;

/// Reads `probes` (uv, layer, reference) through `map`'s comparison sampler.
std::vector<float> probe(gpu::Device& device, const gpu::ShadowMapArray& map, const std::vector<glm::vec4>& probes) {
    const VkShaderStageFlags compute = VK_SHADER_STAGE_COMPUTE_BIT;
    gpu::PipelineLayout layout(device,
                               {{0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, compute},
                                {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, compute},
                                {2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, compute}},
                               sizeof(glm::uvec4), compute, "shadowMapTest.probe.layout");
    gpu::ComputePipeline pipeline(device, layout, shadow_map_probe_comp_spv, "shadowMapTest.probe");
    gpu::Buffer in(device, probes.size() * sizeof(glm::vec4), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                   gpu::MemoryUsage::CpuToGpu, "shadowMapTest.probes");
    gpu::Buffer out(device, probes.size() * sizeof(float), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                    gpu::MemoryUsage::GpuToCpu, "shadowMapTest.results");
    in.upload(std::span<const glm::vec4>(probes));
    device.submitImmediate(
        [&](VkCommandBuffer cmd) {
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.handle());
            const VkDescriptorImageInfo image = map.descriptor();
            const VkDescriptorBufferInfo buffers[2] = {{in.handle(), 0, VK_WHOLE_SIZE}, {out.handle(), 0, VK_WHOLE_SIZE}};
            VkWriteDescriptorSet writes[3] = {};
            for (uint32_t b = 0; b < 3; ++b) {
                writes[b].sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
                writes[b].dstBinding = b;
                writes[b].descriptorCount = 1;
                writes[b].descriptorType = b == 0 ? VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER
                                                  : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
                if (b == 0) writes[b].pImageInfo = &image;
                else writes[b].pBufferInfo = &buffers[b - 1];
            }
            device.fn().cmdPushDescriptorSet(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout.handle(), 0, 3, writes);
            const glm::uvec4 count(uint32_t(probes.size()), 0, 0, 0);
            vkCmdPushConstants(cmd, layout.handle(), compute, 0, sizeof count, &count);
            vkCmdDispatch(cmd, (uint32_t(probes.size()) + 15) / 16, 1, 1);
            gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                               VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
        },
        "shadowMapTest.probe");
    const auto* mapped = static_cast<const float*>(out.mapped());
    return std::vector<float>(mapped, mapped + probes.size());
}

/// Probes at the layer's centre in front of and behind kDrawnDepth, and
/// one outside the map, for every layer.
std::vector<glm::vec4> probes() {
    std::vector<glm::vec4> p;
    for (uint32_t layer = 0; layer < kLayers; ++layer) {
        p.emplace_back(0.5f, 0.5f, float(layer), kDrawnDepth - 0.1f);
        p.emplace_back(0.5f, 0.5f, float(layer), kDrawnDepth + 0.1f);
        p.emplace_back(1.5f, 0.5f, float(layer), kDrawnDepth + 0.1f);
    }
    return p;
}

} // namespace

TEST(ShadowMapArray, DepthPassShadowsOnlyItsLayerBehindTheCaster) {
    std::string why;
    gpu::Device* device = GpuTestDevice::get(why);
    if (!device) GTEST_SKIP() << "no Vulkan device: " << why;
    const uint64_t messagesBefore = GpuTestDevice::validationMessages();
    {
        gpu::ShadowMapArray map(*device, kSize, kLayers, "shadowMapTest.map");
        EXPECT_EQ(map.layers(), kLayers);
        EXPECT_EQ(map.bytes(), uint64_t(kSize) * kSize * kLayers * 4u);
        for (float lit : probe(*device, map, probes())) EXPECT_EQ(lit, 1.0f) << "a new map must read lit";

        gpu::PipelineLayout layout(*device, {}, sizeof(glm::vec4), VK_SHADER_STAGE_VERTEX_BIT,
                                   "shadowMapTest.depth.layout");
        gpu::GraphicsPipelineDesc desc;
        desc.name = "shadowMapTest.depth";
        desc.layout = &layout;
        desc.stages = {{VK_SHADER_STAGE_VERTEX_BIT, shadow_map_depth_vert_spv}};
        desc.cullMode = VK_CULL_MODE_NONE;
        desc.depthFormat = gpu::ShadowMapArray::kFormat;
        desc.depthBiasConstant = 1.0f; // the backends' casters are biased too: must be accepted
        gpu::Pipeline pipeline(*device, desc);
        device->submitImmediate(
            [&](VkCommandBuffer cmd) {
                map.beginWriting(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT);
                for (uint32_t layer = 0; layer < kLayers; ++layer) {
                    map.beginLayer(cmd, layer);
                    if (layer == kDrawnLayer) {
                        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline.handle());
                        const glm::vec4 depth(kDrawnDepth, 0.0f, 0.0f, 0.0f);
                        vkCmdPushConstants(cmd, layout.handle(), VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof depth, &depth);
                        vkCmdDraw(cmd, 3, 1, 0, 0);
                    }
                    map.endLayer(cmd);
                }
                map.endWriting(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT);
            },
            "shadowMapTest.depth");

        const std::vector<float> lit = probe(*device, map, probes());
        for (uint32_t layer = 0; layer < kLayers; ++layer) {
            const float* p = &lit[layer * 3];
            EXPECT_EQ(p[0], 1.0f) << "layer " << layer << ": in front of the caster";
            EXPECT_EQ(p[1], layer == kDrawnLayer ? 0.0f : 1.0f) << "layer " << layer << ": behind the caster";
            EXPECT_EQ(p[2], 1.0f) << "layer " << layer << ": outside the map";
        }

        // A later write of the same frame (a crowd after the characters)
        // keeps the layers' depths; the next frame's first write clears them.
        using Contents = gpu::ShadowMapArray::Contents;
        auto writeNothing = [&](Contents contents) {
            device->submitImmediate(
                [&](VkCommandBuffer cmd) {
                    map.beginWriting(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, contents);
                    for (uint32_t layer = 0; layer < kLayers; ++layer) {
                        map.beginLayer(cmd, layer, contents);
                        map.endLayer(cmd);
                    }
                    map.endWriting(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT);
                },
                "shadowMapTest.rewrite");
        };
        writeNothing(Contents::Keep);
        EXPECT_EQ(probe(*device, map, probes())[kDrawnLayer * 3 + 1], 0.0f) << "a kept layer lost its caster";
        writeNothing(Contents::Clear);
        EXPECT_EQ(probe(*device, map, probes())[kDrawnLayer * 3 + 1], 1.0f) << "a cleared layer kept its caster";
        device->waitIdle();
    }
    EXPECT_EQ(GpuTestDevice::validationMessages(), messagesBefore) << "validation messages (see stderr)";
}
