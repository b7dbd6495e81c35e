// The whole GPU evaluation against OpenSubdiv on the CPU (issue 14: "Far/Bfr
// versus GPU positions and normals on every test shape and on the
// creature"): every shape's
// packed surface in GpuSubdiv, as every backend holds it, its refined
// points, and the shaders' own tsSubdivEvaluate in a compute shader at a
// 5 x 5 grid of every domain (edges and corners included, where the owner
// rule hands the point to a neighbour), against SubdivSurface's Far
// evaluation at the same ptex point (held to Bfr within 1e-7 of the
// diagonal in tests/subdiv). Positions within 1e-5 of the bounding-box
// diagonal, normals within 0.1 degree where the surface has one. The
// backends' refinement equals the CPU's bit for bit
// (SubdivBackendsGpu.RefinedPointsEqualTheCpuStencilsOnEveryBackend), and
// their images agree (EmulatedImagesMatchHulldomain), so this holds on all
// three.
#include "common/GpuSubdiv.h"
#include "GpuTestDevice.h"
#include "OsdShapes.h"

#include "tessera/assets/GltfLoader.h"
#include "tessera/gpu/Barriers.h"
#include "tessera/gpu/Buffer.h"
#include "tessera/gpu/ComputePipeline.h"
#include "tessera/gpu/PipelineLayout.h"
#include "tessera/subdiv/ObjShape.h"
#include "tessera/subdiv/SubdivDomains.h"
#include "tessera/subdiv/SubdivGpuMesh.h"
#include "tessera/subdiv/SubdivSurface.h"
#include "tessera/subdiv/TriangleCage.h"

#include "subdiv_pipeline.comp.spv.h"

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
    uint32_t domain;
    glm::vec2 uv;
};

/// Runs the compute shader over `samples` of `surface` (its points already
/// refined): per sample position, d/du, d/dv.
std::vector<glm::vec4> evaluateOnGpu(gpu::Device& device, backends::GpuSubdiv& surface,
                                     const std::vector<glm::vec4>& refined, const std::vector<Sample>& samples) {
    shader::SubdivUniforms u{};
    u.model = glm::mat4(1.0f);
    u.normalMatrix = glm::mat4(1.0f);
    u.lod = glm::vec4(6.0f, 64.0f, 1.0f, 0.0f);
    u.placement = glm::vec4(1.0f, 0.0f, 0.0f, 0.0f); // the base surface
    u.modes = glm::uvec4(TS_SUBDIV_NORMALS_APPROXIMATE, 0u, TS_SUBDIV_VIEW_SHADED, surface.domainCount());
    const gpu::MemoryUsage up = gpu::MemoryUsage::CpuToGpu;
    gpu::Buffer uniforms(device, sizeof u, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, up, "subdivPipelineTest.uniforms");
    uniforms.upload(std::span<const shader::SubdivUniforms>(&u, 1));
    gpu::Buffer staging(device, refined.size() * sizeof(glm::vec4), VK_BUFFER_USAGE_TRANSFER_SRC_BIT, up,
                        "subdivPipelineTest.points");
    staging.upload(std::span<const glm::vec4>(refined));
    std::vector<glm::vec4> in;
    for (const Sample& s : samples) in.emplace_back(std::bit_cast<float>(s.domain), s.uv.x, s.uv.y, 0.0f);
    gpu::Buffer input(device, in.size() * sizeof(glm::vec4), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, up,
                      "subdivPipelineTest.samples");
    input.upload(std::span<const glm::vec4>(in));
    gpu::Buffer results(device, samples.size() * 3 * sizeof(glm::vec4), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                        gpu::MemoryUsage::GpuToCpu, "subdivPipelineTest.results");

    const VkShaderStageFlags compute = VK_SHADER_STAGE_COMPUTE_BIT;
    std::vector<gpu::BindingDesc> bindings = backends::GpuSubdiv::evalBindings(compute);
    bindings.push_back({50, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, compute});
    bindings.push_back({51, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, compute});
    gpu::PipelineLayout layout(device, bindings, sizeof(uint32_t), compute, "subdivPipelineTest.layout");
    gpu::ComputePipeline pipeline(device, layout, subdiv_pipeline_comp_spv, "subdivPipelineTest");

    const uint32_t count = uint32_t(samples.size());
    device.submitImmediate(
        [&](VkCommandBuffer cmd) {
            const VkBufferCopy copy{0, 0, refined.size() * sizeof(glm::vec4)};
            vkCmdCopyBuffer(cmd, staging.handle(), surface.points().handle(), 1, &copy);
            gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                               VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_READ_BIT);
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.handle());
            std::vector<VkWriteDescriptorSet> writes =
                surface.evalWrites({uniforms.handle(), 0, sizeof u, nullptr});
            const VkDescriptorBufferInfo infos[2] = {{input.handle(), 0, VK_WHOLE_SIZE},
                                                     {results.handle(), 0, VK_WHOLE_SIZE}};
            for (uint32_t b = 0; b < 2; ++b) {
                VkWriteDescriptorSet w{};
                w.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
                w.dstBinding = 50 + b;
                w.descriptorCount = 1;
                w.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
                w.pBufferInfo = &infos[b];
                writes.push_back(w);
            }
            device.fn().cmdPushDescriptorSet(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout.handle(), 0,
                                             uint32_t(writes.size()), writes.data());
            vkCmdPushConstants(cmd, layout.handle(), compute, 0, sizeof count, &count);
            vkCmdDispatch(cmd, (count + 63) / 64, 1, 1);
            gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                               VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
        },
        "subdivPipelineTest");
    const auto* mapped = static_cast<const glm::vec4*>(results.mapped());
    return std::vector<glm::vec4>(mapped, mapped + samples.size() * 3);
}

double angleDegrees(const glm::dvec3& a, const glm::dvec3& b) {
    const double c = glm::dot(glm::normalize(a), glm::normalize(b));
    return std::acos(std::clamp(c, -1.0, 1.0)) * 180.0 / 3.14159265358979323846;
}

/// How far the GPU's normals may stray from Far's: everywhere (`worst`),
/// and the fraction of samples allowed beyond 0.1 degree.
struct NormalTolerance {
    double worst = 0.1;
    double fractionBeyond = 0.0;
};

/// Evaluates `shape` on the GPU at a `grid` x `grid` grid of every domain
/// and checks it against Far; `name` for the messages.
void checkShape(gpu::Device& device, const subdiv::ObjShape& shape, const std::string& name, int grid,
                NormalTolerance tolerance = {}) {
    SCOPED_TRACE(name);
    auto surface = subdiv::SubdivSurface::create(shape);
    ASSERT_TRUE(surface) << surface.error().message;
    auto mesh = subdiv::SubdivGpuMesh::build(shape, surface.value());
    ASSERT_TRUE(mesh) << mesh.error().message;
    auto domains = subdiv::SubdivDomains::build(shape);
    ASSERT_TRUE(domains) << domains.error().message;
    backend::SubdivDesc desc;
    desc.mesh = &mesh.value();
    auto gpuSurface =
        backends::GpuSubdiv::create(device, desc, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    ASSERT_TRUE(gpuSurface) << gpuSurface.error().message;

    std::vector<Sample> samples;
    for (uint32_t d = 0; d < mesh.value().domainCount(); ++d) {
        if (mesh.value().domains[d].topology.w & TS_SUBDIV_DOMAIN_HOLE) continue;
        for (int j = 0; j <= grid; ++j)
            for (int i = 0; i <= grid; ++i) samples.push_back({d, glm::vec2(float(i) / grid, float(j) / grid)});
    }
    const std::vector<glm::vec4> gpu =
        evaluateOnGpu(device, *gpuSurface.value(), mesh.value().refine(shape.positions), samples);
    const double diagonal = surface.value().boundsDiagonal();
    double worstPosition = 0.0, worstNormal = 0.0;
    size_t normals = 0, evaluated = 0, beyond = 0;
    for (size_t k = 0; k < samples.size(); ++k) {
        const uint32_t ptex = domains.value().placement(samples[k].domain).ptexFace;
        const glm::vec2 uv = domains.value().toPtex(samples[k].domain, samples[k].uv);
        const std::optional<subdiv::LimitPoint> cpu = surface.value().evaluatePtex(ptex, glm::dvec2(uv));
        if (!cpu) continue;
        ++evaluated;
        const glm::dvec3 position(gpu[3 * k]), du(gpu[3 * k + 1]), dv(gpu[3 * k + 2]);
        worstPosition = std::max(worstPosition, glm::length(position - cpu->position) / diagonal);
        // Where the surface has a normal: not at a degenerate corner of an
        // end cap or a sharp corner, where the derivatives vanish.
        const glm::dvec3 n = cpu->normal();
        if (glm::length(n) > 1e-6 * diagonal * diagonal && glm::length(glm::cross(du, dv)) > 0.0) {
            const double angle = angleDegrees(glm::cross(du, dv), n);
            worstNormal = std::max(worstNormal, angle);
            beyond += angle > 0.1;
            ++normals;
        }
    }
    std::cout << "[subdiv pipeline] " << name << ": " << mesh.value().domainCount() << " domains, " << evaluated
              << " samples, worst position " << worstPosition << " of the diagonal, worst normal " << worstNormal
              << " deg over " << normals << " samples, " << beyond << " beyond 0.1 deg\n";
    EXPECT_GT(evaluated, 0u);
    EXPECT_LE(worstPosition, 1e-5);
    EXPECT_LE(worstNormal, tolerance.worst);
    EXPECT_LE(double(beyond), tolerance.fractionBeyond * double(normals));
}

} // namespace

TEST(SubdivPipelineGpu, EvaluationMatchesOpenSubdivOnEveryShape) {
    std::string why;
    gpu::Device* device = GpuTestDevice::get(why);
    if (!device) GTEST_SKIP() << "no Vulkan device: " << why;
    const uint64_t messagesBefore = GpuTestDevice::validationMessages();
    const std::vector<std::filesystem::path> files = osdShapeFiles();
    ASSERT_GE(files.size(), 12u) << "OpenSubdiv's shapes in " << TESSERA_TESTDATA_DIR;
    for (const auto& file : files) {
        auto shape = subdiv::readObjShape(file);
        ASSERT_TRUE(shape) << shape.error().message;
        checkShape(*device, shape.value(), file.filename().string(), 4);
    }
    EXPECT_EQ(GpuTestDevice::validationMessages(), messagesBefore) << "validation messages during the dispatches";
}

// The creature's cage as the demo draws it (froblin_1.glb welded,
// TriangleCage.h): 15,000 domains, every one a sub-face of a triangle and
// most next to an extraordinary vertex.
TEST(SubdivPipelineGpu, EvaluationMatchesOpenSubdivOnTheCreature) {
    std::string why;
    gpu::Device* device = GpuTestDevice::get(why);
    if (!device) GTEST_SKIP() << "no Vulkan device: " << why;
    const uint64_t messagesBefore = GpuTestDevice::validationMessages();
    const std::filesystem::path file = std::filesystem::path(TESSERA_CONTENT_DIR) / "characters" / "froblin_1.glb";
    ASSERT_TRUE(std::filesystem::exists(file)) << file << " (the build makes it)";
    auto asset = assets::loadCharacter(file);
    ASSERT_TRUE(asset) << asset.error().message;
    std::vector<glm::vec3> positions;
    for (const auto& v : asset.value().cage.vertices) positions.push_back(v.position);
    auto cage = subdiv::weldTriangleCage(positions, asset.value().cage.indices, file.string());
    ASSERT_TRUE(cage) << cage.error().message;
    // Its patches are a few millimetres across and its sub-faces meet at
    // every triangle's centre (valence 3, Gregory end caps): there, float
    // tangents that are nearly parallel (cos -0.99 at the centre of a thin
    // triangle) or come from the end caps' rational weights near an edge
    // leave a handful of the 135,000 normals up to 0.15 degree off the
    // double-precision ones; positions stay within 3.2e-7 of the diagonal.
    checkShape(*device, cage.value().shape, "froblin_1 (welded cage)", 2, {0.25, 1e-4});
    EXPECT_EQ(GpuTestDevice::validationMessages(), messagesBefore) << "validation messages during the dispatches";
}
