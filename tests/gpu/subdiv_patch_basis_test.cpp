// The base surfaces on the GPU against the CPU: OpenSubdiv's GLSL patch
// basis (subdiv_patch.glsl, generated from Osd::GLSLPatchShaderSource) in a
// compute shader, in float, on every patch of every OpenSubdiv regression
// shape at a 7 x 7 grid of (s, t) corners and edges included, against
// SubdivSurface's double-precision Far evaluation (which tests/subdiv holds
// to OpenSubdiv's Bfr within 1e-7 of the bounding-box diagonal): positions
// within 1e-5 of the diagonal, normals within 0.1 degree where the surface
// has one. What the domain and evaluation vertex shaders will compute.
#include "GpuTestDevice.h"
#include "OsdShapes.h"

#include "tessera/gpu/Barriers.h"
#include "tessera/gpu/Buffer.h"
#include "tessera/gpu/ComputePipeline.h"
#include "tessera/gpu/PipelineLayout.h"
#include "tessera/subdiv/ObjShape.h"
#include "tessera/subdiv/SubdivSurface.h"

#include "subdiv_eval.comp.spv.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <vector>

using namespace tessera;
using namespace tessera::test;

namespace {

struct Sample {
    uint32_t patch;
    glm::dvec2 st;
};

template <typename T>
gpu::Buffer upload(gpu::Device& device, const std::vector<T>& data, gpu::MemoryUsage memory, const char* name) {
    gpu::Buffer buffer(device, std::max<VkDeviceSize>(data.size() * sizeof(T), 16), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                       memory, name);
    if (!data.empty()) buffer.upload(std::span<const T>(data));
    return buffer;
}

/// Evaluates `samples` of `surface` with the compute shader: per sample
/// position, d/du, d/dv.
std::vector<glm::vec4> evaluateOnGpu(gpu::Device& device, const subdiv::SubdivSurface& surface,
                                     const std::vector<Sample>& samples) {
    std::vector<glm::vec4> points;
    for (const glm::vec3& p : surface.controlPoints()) points.emplace_back(p, 1.0f);
    const std::vector<uint32_t> indices(surface.patchPointIndices().begin(), surface.patchPointIndices().end());
    std::vector<glm::uvec4> patches;
    for (const subdiv::Patch& p : surface.patches())
        patches.emplace_back(uint32_t(p.type), p.firstIndex, p.param.field0, p.param.field1);
    std::vector<glm::vec4> in;
    for (const Sample& s : samples)
        in.emplace_back(std::bit_cast<float>(s.patch), float(s.st.x), float(s.st.y), 0.0f);

    const VkShaderStageFlags compute = VK_SHADER_STAGE_COMPUTE_BIT;
    std::vector<gpu::BindingDesc> bindings;
    for (uint32_t b = 0; b < 5; ++b) bindings.push_back({b, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, compute});
    gpu::PipelineLayout layout(device, bindings, sizeof(uint32_t), compute, "subdivEvalTest.layout");
    gpu::ComputePipeline pipeline(device, layout, subdiv_eval_comp_spv, "subdivEvalTest");
    const gpu::MemoryUsage up = gpu::MemoryUsage::CpuToGpu;
    gpu::Buffer buffers[5] = {upload(device, points, up, "subdivEvalTest.points"),
                              upload(device, indices, up, "subdivEvalTest.indices"),
                              upload(device, patches, up, "subdivEvalTest.patches"),
                              upload(device, in, up, "subdivEvalTest.samples"),
                              gpu::Buffer(device, samples.size() * 3 * sizeof(glm::vec4), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                          gpu::MemoryUsage::GpuToCpu, "subdivEvalTest.results")};
    const uint32_t count = uint32_t(samples.size());
    device.submitImmediate(
        [&](VkCommandBuffer cmd) {
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.handle());
            VkDescriptorBufferInfo infos[5];
            VkWriteDescriptorSet writes[5] = {};
            for (uint32_t b = 0; b < 5; ++b) {
                infos[b] = {buffers[b].handle(), 0, VK_WHOLE_SIZE};
                writes[b].sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
                writes[b].dstBinding = b;
                writes[b].descriptorCount = 1;
                writes[b].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
                writes[b].pBufferInfo = &infos[b];
            }
            device.fn().cmdPushDescriptorSet(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout.handle(), 0, 5, writes);
            vkCmdPushConstants(cmd, layout.handle(), compute, 0, sizeof count, &count);
            vkCmdDispatch(cmd, (count + 63) / 64, 1, 1);
            gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                               VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
        },
        "subdivEvalTest");
    const auto* mapped = static_cast<const glm::vec4*>(buffers[4].mapped());
    return std::vector<glm::vec4>(mapped, mapped + samples.size() * 3);
}

double angleDegrees(const glm::dvec3& a, const glm::dvec3& b) {
    const double c = glm::dot(glm::normalize(a), glm::normalize(b));
    return std::acos(std::clamp(c, -1.0, 1.0)) * 180.0 / 3.14159265358979323846;
}

} // namespace

TEST(SubdivPatchBasisGpu, OpenSubdivGlslMatchesFarOnEveryShape) {
    std::string why;
    gpu::Device* device = GpuTestDevice::get(why);
    if (!device) GTEST_SKIP() << "no Vulkan device: " << why;
    const uint64_t messagesBefore = GpuTestDevice::validationMessages();
    const std::vector<std::filesystem::path> files = osdShapeFiles();
    ASSERT_GE(files.size(), 12u) << "OpenSubdiv's shapes in " << TESSERA_TESTDATA_DIR;
    for (const auto& file : files) {
        SCOPED_TRACE(file.filename().string());
        auto shape = subdiv::readObjShape(file);
        ASSERT_TRUE(shape) << shape.error().message;
        auto created = subdiv::SubdivSurface::create(shape.value());
        ASSERT_TRUE(created) << created.error().message;
        const subdiv::SubdivSurface& surface = created.value();
        std::vector<Sample> samples;
        for (uint32_t p = 0; p < surface.patches().size(); ++p)
            for (int j = 0; j <= 6; ++j)
                for (int i = 0; i <= 6; ++i) samples.push_back({p, glm::dvec2(i / 6.0, j / 6.0)});
        const std::vector<glm::vec4> gpu = evaluateOnGpu(*device, surface, samples);
        const double diagonal = surface.boundsDiagonal();
        double worstPosition = 0.0, worstNormal = 0.0;
        size_t normals = 0;
        for (size_t k = 0; k < samples.size(); ++k) {
            const subdiv::LimitPoint cpu = surface.evaluatePatch(samples[k].patch, samples[k].st);
            const glm::dvec3 position(gpu[3 * k]), du(gpu[3 * k + 1]), dv(gpu[3 * k + 2]);
            worstPosition = std::max(worstPosition, glm::length(position - cpu.position) / diagonal);
            const glm::dvec3 n = glm::cross(cpu.du, cpu.dv);
            // Where the surface has a normal: not at a degenerate corner of
            // an end cap or a sharp corner, where the derivatives vanish.
            if (glm::length(n) > 1e-6 * diagonal * diagonal) {
                worstNormal = std::max(worstNormal, angleDegrees(glm::cross(du, dv), n));
                ++normals;
            }
        }
        std::cout << "[subdiv gpu] " << file.filename().string() << ": " << surface.patches().size() << " patches, "
                  << samples.size() << " samples, worst position " << worstPosition << " of the diagonal, worst normal "
                  << worstNormal << " deg over " << normals << " samples\n";
        EXPECT_LE(worstPosition, 1e-5);
        EXPECT_LE(worstNormal, 0.1);
    }
    EXPECT_EQ(GpuTestDevice::validationMessages(), messagesBefore) << "validation messages during the dispatches";
}
