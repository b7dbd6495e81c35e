// The compressed vertex format in GLSL against C++ (CompressedVertex.h is
// compiled by both): a compute shader packs the same vertices as the C++
// reference and unpacks the C++ words; the words must agree field by field
// within one code where a float rounding tie lands differently (counted and
// bounded), and the decoded values within 1e-5.
#include "CompressedVertexTestLayout.h"
#include "tessera/gpu/Barriers.h"
#include "GpuTestDevice.h"

#include "tessera/core/Random.h"
#include "tessera/gpu/Buffer.h"
#include "tessera/gpu/ComputePipeline.h"
#include "tessera/gpu/PipelineLayout.h"

#include "tessera/shaders/CompressedVertex.h"
#include "compressed_vertex.comp.spv.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <iterator>
#include <string>
#include <vector>

using namespace tessera;
using namespace tessera::shader;
using namespace tessera::test;

namespace {

struct Field {
    const char* name;
    uint32_t word, shift, bits;
};
// Figure 10, field by field.
constexpr Field kFields[] = {{"X", 0, 16, 16},  {"Y", 0, 0, 16},   {"Z", 0, 16, 16},  {"Ttheta", 1, 8, 8},
                             {"Tphi", 1, 0, 8}, {"Nx", 2, 22, 10}, {"Ny", 2, 11, 11}, {"Nz", 2, 0, 11},
                             {"U", 3, 16, 16},  {"V", 3, 0, 16}};

// Distance between two codes of a field; SNORM normal fields compare as
// signed values so -1 and +0 count as one step, not 2^bits - 1.
uint32_t codeDistance(const Field& f, uint32_t a, uint32_t b, bool isSigned) {
    const uint32_t mask = (1u << f.bits) - 1u;
    int32_t x = int32_t((a >> f.shift) & mask), y = int32_t((b >> f.shift) & mask);
    if (isSigned) {
        if (x >= int32_t(1u << (f.bits - 1))) x -= int32_t(1u << f.bits);
        if (y >= int32_t(1u << (f.bits - 1))) y -= int32_t(1u << f.bits);
    }
    return uint32_t(std::abs(x - y));
}

vec3 randomUnit(Random& rng) {
    for (;;) {
        const vec3 v(rng.range(-1.0f, 1.0f), rng.range(-1.0f, 1.0f), rng.range(-1.0f, 1.0f));
        const float len = glm::length(v);
        if (len > 0.05f && len <= 1.0f) return v / len;
    }
}

// Random vertices inside the ranges plus the edge cases of the C++ test:
// box corners, poles (s == 0 tangents), axis normals, uv range ends.
std::vector<TsCvTestInput> makeInputs(const TsCvTestParams& p, uint32_t seed) {
    std::vector<TsCvTestInput> inputs;
    const vec3 lo(p.boxMin), hi(p.boxMax);
    const vec2 uvLo(p.uvRange.x, p.uvRange.y), uvHi(p.uvRange.z, p.uvRange.w);
    const vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (int corner = 0; corner < 8; ++corner) {
        for (const vec3& axis : axes) {
            TsCvTestInput in{};
            in.position = vec4((corner & 1) ? hi.x : lo.x, (corner & 2) ? hi.y : lo.y, (corner & 4) ? hi.z : lo.z, 1);
            in.normal = vec4(axis, 0);
            in.tangent = vec4(axis.z, axis.x, axis.y, 0);
            in.uv = vec4((corner & 1) ? uvHi.x : uvLo.x, (corner & 2) ? uvHi.y : uvLo.y, 0, 0);
            inputs.push_back(in);
        }
    }
    Random rng(seed);
    for (int i = 0; i < 8192; ++i) {
        TsCvTestInput in{};
        in.position = vec4(glm::mix(lo, hi, vec3(rng.nextFloat(), rng.nextFloat(), rng.nextFloat())), 1);
        const vec3 n = randomUnit(rng);
        in.normal = vec4(n, 0);
        in.tangent = vec4(glm::normalize(glm::cross(n, randomUnit(rng))), 0);
        in.uv = vec4(glm::mix(uvLo, uvHi, vec2(rng.nextFloat(), rng.nextFloat())), 0, 0);
        inputs.push_back(in);
    }
    for (TsCvTestInput& in : inputs) {
        in.cpuWord =
            tsPackVertex(vec3(in.position), vec3(in.normal), vec3(in.tangent), vec2(in.uv), lo, hi, uvLo, uvHi);
    }
    return inputs;
}

std::vector<TsCvTestOutput> runShader(gpu::Device& device, const TsCvTestParams& params,
                                      const std::vector<TsCvTestInput>& inputs) {
    const VkShaderStageFlags compute = VK_SHADER_STAGE_COMPUTE_BIT;
    gpu::PipelineLayout layout(
        device, {{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, compute}, {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, compute}},
        sizeof(TsCvTestParams), compute, "compressedVertexTest.layout");
    gpu::ComputePipeline pipeline(device, layout, compressed_vertex_comp_spv, "compressedVertexTest");
    const VkDeviceSize inBytes = inputs.size() * sizeof(TsCvTestInput);
    const VkDeviceSize outBytes = inputs.size() * sizeof(TsCvTestOutput);
    gpu::Buffer in(device, inBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, gpu::MemoryUsage::CpuToGpu,
                   "compressedVertexTest.inputs");
    gpu::Buffer out(device, outBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, gpu::MemoryUsage::GpuToCpu,
                    "compressedVertexTest.outputs");
    in.upload(std::span<const TsCvTestInput>(inputs));
    device.submitImmediate(
        [&](VkCommandBuffer cmd) {
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.handle());
            const VkDescriptorBufferInfo infos[2] = {{in.handle(), 0, VK_WHOLE_SIZE}, {out.handle(), 0, VK_WHOLE_SIZE}};
            VkWriteDescriptorSet writes[2] = {};
            for (uint32_t b = 0; b < 2; ++b) {
                writes[b].sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
                writes[b].dstBinding = b;
                writes[b].descriptorCount = 1;
                writes[b].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
                writes[b].pBufferInfo = &infos[b];
            }
            device.fn().cmdPushDescriptorSet(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout.handle(), 0, 2, writes);
            vkCmdPushConstants(cmd, layout.handle(), compute, 0, sizeof params, &params);
            vkCmdDispatch(cmd, (params.count.x + 63) / 64, 1, 1);
            tessera::gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_HOST_BIT,
                                        VK_ACCESS_2_HOST_READ_BIT);
        },
        "compressedVertexTest");
    const auto* mapped = static_cast<const TsCvTestOutput*>(out.mapped());
    return std::vector<TsCvTestOutput>(mapped, mapped + inputs.size());
}

void expectNear(const vec4& a, const vec4& b, int n, const char* what, size_t i) {
    for (int c = 0; c < n; ++c) EXPECT_NEAR(a[c], b[c], 1e-5f) << what << " of vertex " << i << " component " << c;
}

class CompressedVertexGpu : public ::testing::TestWithParam<int> {};

} // namespace

TEST_P(CompressedVertexGpu, GlslMatchesCpp) {
    std::string why;
    gpu::Device* device = GpuTestDevice::get(why);
    if (!device) GTEST_SKIP() << "no Vulkan device: " << why;
    const uint64_t messagesBefore = GpuTestDevice::validationMessages();

    TsCvTestParams params{};
    if (GetParam() == 0) { // the paper's ranges: uv in [0, 1]
        params.boxMin = vec4(-1.0f, 0.0f, -0.5f, 0.0f);
        params.boxMax = vec4(1.0f, 2.0f, 0.5f, 0.0f);
        params.uvRange = vec4(0.0f, 0.0f, 1.0f, 1.0f);
    } else { // an off-centre box and uvs outside [0, 1]
        params.boxMin = vec4(-7.25f, 3.5f, 100.0f, 0.0f);
        params.boxMax = vec4(-0.125f, 9.0f, 101.5f, 0.0f);
        params.uvRange = vec4(-2.0f, 0.5f, 3.0f, 4.0f);
    }
    const std::vector<TsCvTestInput> inputs = makeInputs(params, 1234u + uint32_t(GetParam()));
    params.count = uvec4(uint32_t(inputs.size()), 0, 0, 0);
    const std::vector<TsCvTestOutput> outputs = runShader(*device, params, inputs);
    EXPECT_EQ(GpuTestDevice::validationMessages(), messagesBefore) << "validation messages during the dispatch";

    const vec3 lo(params.boxMin), hi(params.boxMax);
    const vec2 uvLo(params.uvRange.x, params.uvRange.y), uvHi(params.uvRange.z, params.uvRange.w);
    uint32_t tieFields = 0, tieWords = 0;
    uint32_t tiesPerField[std::size(kFields)] = {};
    for (size_t i = 0; i < inputs.size(); ++i) {
        const uvec4 cpu = inputs[i].cpuWord, gpu = outputs[i].gpuWord;
        bool tie = false;
        for (size_t k = 0; k < std::size(kFields); ++k) {
            const Field& f = kFields[k];
            const uint32_t d = codeDistance(f, cpu[int(f.word)], gpu[int(f.word)], f.word == 2);
            EXPECT_LE(d, 1u) << f.name << " of vertex " << i;
            if (d == 1) {
                ++tiesPerField[k];
                ++tieFields;
                tie = true;
            }
        }
        if (tie) ++tieWords;
        vec3 position, normal, tangent;
        vec2 uv;
        tsUnpackVertex(cpu, lo, hi, uvLo, uvHi, position, normal, tangent, uv);
        expectNear(outputs[i].position, vec4(position, 1.0f), 3, "position", i);
        expectNear(outputs[i].normal, vec4(normal, 0.0f), 3, "normal", i);
        expectNear(outputs[i].tangent, vec4(tangent, 0.0f), 3, "tangent", i);
        expectNear(outputs[i].uv, vec4(uv, 0.0f, 0.0f), 2, "uv", i);
        if (HasFailure()) FAIL() << "stopping at vertex " << i;
    }
    // A one-code difference needs a value within a few float ulps of a
    // rounding tie (x.5 codes); with GLSL's looser division and
    // transcendental precision that is rare, but not impossible.
    std::string perField;
    for (size_t k = 0; k < std::size(kFields); ++k) {
        if (tiesPerField[k]) perField += std::string(" ") + kFields[k].name + "=" + std::to_string(tiesPerField[k]);
    }
    std::printf("[          ] %u of %zu words (%u fields:%s) differ by one code\n", tieWords, inputs.size(), tieFields,
                perField.c_str());
    EXPECT_LE(tieWords, inputs.size() / 100) << "more than 1% of the words differ";
}

INSTANTIATE_TEST_SUITE_P(Ranges, CompressedVertexGpu, ::testing::Values(0, 1));
