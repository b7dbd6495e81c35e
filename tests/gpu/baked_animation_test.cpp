// Baked animation in GLSL against C++: a compute shader calls tsBakedJoint
// (baked_animation.glsl) on an RGBA32F uniform texel buffer, the format every
// backend reads, and the matrices must equal character::evaluateBakedJoint
// within float rounding (same frames and weight from the shared
// tsBakedFramePair; GLSL may round mix() differently).
#include "BakedAnimationTestLayout.h"
#include "GpuTestDevice.h"

#include "tessera/character/BakedAnimation.h"
#include "tessera/core/Random.h"
#include "tessera/gpu/Barriers.h"
#include "tessera/gpu/Buffer.h"
#include "tessera/gpu/BufferView.h"
#include "tessera/gpu/ComputePipeline.h"
#include "tessera/gpu/PipelineLayout.h"

#include "../content/GlbTestCharacter.h"
#include "baked_animation.comp.spv.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace tessera;
using namespace tessera::shader;
using namespace tessera::test;

namespace {

std::vector<mat4> runShader(gpu::Device& device, const character::BakedAnimation& baked,
                            const std::vector<TsBakedTestQuery>& queries) {
    const VkShaderStageFlags compute = VK_SHADER_STAGE_COMPUTE_BIT;
    gpu::PipelineLayout layout(device,
                               {{0, VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER, compute},
                                {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, compute},
                                {2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, compute},
                                {3, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, compute}},
                               sizeof(TsBakedTestParams), compute, "bakedAnimationTest.layout");
    gpu::ComputePipeline pipeline(device, layout, baked_animation_comp_spv, "bakedAnimationTest");
    const VkDeviceSize rowBytes = baked.rows.size() * sizeof(vec4);
    gpu::Buffer rows(device, rowBytes, VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT, gpu::MemoryUsage::CpuToGpu,
                     "bakedAnimationTest.rows");
    gpu::BufferView view(device, rows, VK_FORMAT_R32G32B32A32_SFLOAT, 0, rowBytes, "bakedAnimationTest.rowsView");
    gpu::Buffer clips(device, baked.clips.size() * sizeof(BakedClip), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                      gpu::MemoryUsage::CpuToGpu, "bakedAnimationTest.clips");
    gpu::Buffer in(device, queries.size() * sizeof(TsBakedTestQuery), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                   gpu::MemoryUsage::CpuToGpu, "bakedAnimationTest.queries");
    gpu::Buffer out(device, queries.size() * sizeof(mat4), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                    gpu::MemoryUsage::GpuToCpu, "bakedAnimationTest.outputs");
    rows.upload(std::span<const vec4>(baked.rows));
    clips.upload(std::span<const BakedClip>(baked.clips));
    in.upload(std::span<const TsBakedTestQuery>(queries));
    const TsBakedTestParams params{uvec4(uint32_t(queries.size()), 0u, 0u, 0u)};
    device.submitImmediate(
        [&](VkCommandBuffer cmd) {
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.handle());
            const VkBufferView texelView = view.handle();
            const VkDescriptorBufferInfo infos[3] = {
                {clips.handle(), 0, VK_WHOLE_SIZE}, {in.handle(), 0, VK_WHOLE_SIZE}, {out.handle(), 0, VK_WHOLE_SIZE}};
            VkWriteDescriptorSet writes[4] = {};
            for (uint32_t b = 0; b < 4; ++b) {
                writes[b].sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
                writes[b].dstBinding = b;
                writes[b].descriptorCount = 1;
                if (b == 0) {
                    writes[b].descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER;
                    writes[b].pTexelBufferView = &texelView;
                } else {
                    writes[b].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
                    writes[b].pBufferInfo = &infos[b - 1];
                }
            }
            device.fn().cmdPushDescriptorSet(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout.handle(), 0, 4, writes);
            vkCmdPushConstants(cmd, layout.handle(), compute, 0, sizeof params, &params);
            vkCmdDispatch(cmd, (params.count.x + 63) / 64, 1, 1);
            gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                               VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
        },
        "bakedAnimationTest");
    const auto* mapped = static_cast<const mat4*>(out.mapped());
    return std::vector<mat4>(mapped, mapped + queries.size());
}

} // namespace

TEST(BakedAnimationGpu, GlslMatchesCpp) {
    std::string why;
    gpu::Device* device = GpuTestDevice::get(why);
    if (!device) GTEST_SKIP() << "no Vulkan device: " << why;
    const uint64_t messagesBefore = GpuTestDevice::validationMessages();

    // Two characters in one buffer (the second baked one-shot), so the
    // combined offsets, the looping wrap and the clamp all run on the GPU.
    const character::CharacterAsset tube = makeTestCharacter();
    character::CharacterAsset still = tube;
    still.clips.clear();
    const character::BakedAnimation parts[] = {character::bakeAnimation(tube),
                                               character::bakeAnimation(tube, {30.0f, false}),
                                               character::bakeAnimation(still)};
    const character::BakedAnimation baked = character::combine(parts);

    std::vector<TsBakedTestQuery> queries;
    Random rng(77u);
    for (uint32_t clip = 0; clip < baked.clips.size(); ++clip) {
        const BakedClip& record = baked.clips[clip];
        std::vector<float> phases = {0.0f, 1.0f, -0.25f, 1.5f, 2.3f, -3.7f, 0.999999f, 1e-7f};
        for (uint32_t f = 0; f < record.frames.y; ++f) {
            phases.push_back(record.frames.y > 1 ? float(f) / float(record.frames.y - 1) : 0.0f);
        }
        for (int i = 0; i < 200; ++i) phases.push_back(rng.range(-2.0f, 3.0f));
        for (uint32_t joint = 0; joint < record.frames.z; ++joint) {
            for (float phase : phases) queries.push_back({uvec4(clip, joint, 0u, 0u), vec4(phase, 0.0f, 0.0f, 0.0f)});
        }
    }
    const std::vector<mat4> gpu = runShader(*device, baked, queries);
    EXPECT_EQ(GpuTestDevice::validationMessages(), messagesBefore) << "validation messages during the dispatch";

    float worst = 0.0f;
    for (size_t i = 0; i < queries.size(); ++i) {
        const TsBakedTestQuery& q = queries[i];
        const mat4 cpu = character::evaluateBakedJoint(baked, q.clipJoint.x, q.phase.x, q.clipJoint.y);
        for (int c = 0; c < 4; ++c) {
            for (int r = 0; r < 4; ++r) worst = std::max(worst, std::abs(cpu[c][r] - gpu[i][c][r]));
        }
        // Matrix entries are at most ~2 here: a few float ulps of that.
        ASSERT_LE(worst, 2e-6f) << "query " << i << ": clip " << q.clipJoint.x << " joint " << q.clipJoint.y
                                << " phase " << q.phase.x;
    }
    std::printf("[          ] %zu matrices, largest difference %.3g\n", queries.size(), double(worst));
}
