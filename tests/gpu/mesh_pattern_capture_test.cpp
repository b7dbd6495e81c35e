// The mesh-shader tessellation's patterns on the device, against
// Tessellator: the GPU half of tessellator_mesh_pattern_test.cpp and
// tessellator_mesh_triangle_pattern_test.cpp. Test-only task and mesh
// shaders call the meshshader backend's own GLSL (mesh_patches.glsl's
// hand-over for quads, the character's for triangles, mesh_tess.glsl's
// pieces) with the library's tables, and fold every triangle they emit into
// its patch's digest (MeshCaptureTestLayout.h): count, sum and xor of two
// hashes of the canonical triangle's exact bits. Every patch's digest must
// equal the digest of Tessellator::tessellate's triangles for its levels, at
// every level where a point count changes and at 2,000 random level sets,
// each kind in one draw; the mesh primitives query must count exactly
// Tessellator::countTriangles of them all. Skipped, saying why, on a device
// without mesh shaders.
#include "../support/QuadPatternTriangles.h"
#include "GpuTestDevice.h"
#include "MeshCaptureTestLayout.h"

#include "tessera/core/Random.h"
#include "tessera/gpu/Barriers.h"
#include "tessera/gpu/Buffer.h"
#include "tessera/gpu/Pipeline.h"
#include "tessera/gpu/PipelineLayout.h"
#include "tessera/gpu/RenderTarget.h"
#include "tessera/shaders/TessMeshTrianglePattern.h"
#include "tessera/tessellator/MeshPatternLibrary.h"
#include "tessera/tessellator/MeshTrianglePatternLibrary.h"
#include "tessera/tessellator/Tessellator.h"

#include "mesh_capture.frag.spv.h"
#include "mesh_capture_quad.mesh.spv.h"
#include "mesh_capture_quad.task.spv.h"
#include "mesh_capture_triangle.mesh.spv.h"
#include "mesh_capture_triangle.task.spv.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>
#include <span>
#include <string>
#include <vector>

using namespace tessera;
using namespace tessera::test;
using namespace tessera::tessellator;
using shader::TsMeshCapturePatch;
using shader::TsMeshCaptureResult;

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

/// The digest the mesh stage computes (mesh_capture.glsl), of Tessellator's
/// triangles canonicalized as the CPU tests compare them.
TsMeshCaptureResult referenceDigest(Domain domain, const TessFactors& f) {
    const TessellatedPatch patch = Tessellator::tessellate(domain, Partitioning::FractionalOdd, f);
    TsMeshCaptureResult digest{};
    for (size_t i = 0; i < patch.indices.size(); i += 3) {
        PatternTriangle t;
        for (size_t c = 0; c < 3; ++c) t[c] = {patch.uv[patch.indices[i + c]].x, patch.uv[patch.indices[i + c]].y};
        t = canonicalTriangle(t);
        const glm::uvec2 h = shader::tsCaptureHashes({t[0][0], t[0][1]}, {t[1][0], t[1][1]}, {t[2][0], t[2][1]});
        ++digest.triangles;
        digest.hashSum += h.x;
        digest.hashXor ^= h.y;
    }
    return digest;
}

/// One kind's draw: its shaders and tables, the patches, and for triangles
/// the task workgroups' groups of same-level patches.
struct CaptureDraw {
    std::string name;
    std::span<const uint32_t> task, mesh;
    std::span<const shader::TsMeshKey> keys;
    std::span<const uint32_t> triangles;
    std::vector<TsMeshCapturePatch> patches;
    std::vector<glm::uvec4> groups; ///< empty for quads (32 patches a task workgroup)
};

struct CaptureRun {
    std::vector<TsMeshCaptureResult> results; ///< per patch
    std::optional<uint64_t> primitives;       ///< the mesh primitives query, where the device has it
    double seconds = 0;                       ///< the draw's submission, waited for
};

gpu::Buffer storageBuffer(gpu::Device& device, std::span<const std::byte> bytes, const std::string& name) {
    gpu::Buffer buffer(device, bytes.size(), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, gpu::MemoryUsage::GpuOnly, name);
    buffer.upload(bytes);
    return buffer;
}

CaptureRun runCapture(gpu::Device& device, const CaptureDraw& draw) {
    const VkShaderStageFlags stages = VK_SHADER_STAGE_TASK_BIT_EXT | VK_SHADER_STAGE_MESH_BIT_EXT;
    const VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    gpu::PipelineLayout layout(device,
                               {{TS_CAPTURE_BINDING_RESULTS, storage, stages},
                                {TS_CAPTURE_BINDING_GROUPS, storage, stages},
                                {TS_BINDING_MESH_KEYS, storage, stages},
                                {TS_BINDING_MESH_TRIANGLES, storage, stages},
                                {TS_BINDING_MESH_PATCHES, storage, stages}},
                               sizeof(uint32_t), stages, draw.name + ".layout");
    // A 1x1 target: the primitives are rasterized (so the query sees them)
    // but cover one pixel centre per patch.
    gpu::RenderTarget target(device, 1, 1);
    gpu::GraphicsPipelineDesc desc;
    desc.name = draw.name;
    desc.layout = &layout;
    desc.stages = {{VK_SHADER_STAGE_TASK_BIT_EXT, draw.task},
                   {VK_SHADER_STAGE_MESH_BIT_EXT, draw.mesh},
                   {VK_SHADER_STAGE_FRAGMENT_BIT, mesh_capture_frag_spv}};
    desc.cullMode = VK_CULL_MODE_NONE;
    desc.depthTest = desc.depthWrite = false;
    desc.colorFormats = {gpu::RenderTarget::kColorFormat};
    desc.depthFormat = gpu::RenderTarget::kDepthFormat;
    gpu::Pipeline pipeline(device, desc);

    const gpu::Buffer keys = storageBuffer(device, std::as_bytes(draw.keys), draw.name + ".patternKeys");
    const gpu::Buffer triangles = storageBuffer(device, std::as_bytes(draw.triangles), draw.name + ".patternTriangles");
    const gpu::Buffer patches = storageBuffer(device, std::as_bytes(std::span(draw.patches)), draw.name + ".patches");
    gpu::Buffer groups;
    if (!draw.groups.empty())
        groups = storageBuffer(device, std::as_bytes(std::span(draw.groups)), draw.name + ".groups");
    const VkDeviceSize resultBytes = draw.patches.size() * sizeof(TsMeshCaptureResult);
    gpu::Buffer results(device, resultBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                        gpu::MemoryUsage::GpuToCpu, draw.name + ".results");

    VkQueryPool primitives = VK_NULL_HANDLE;
    if (device.features().meshShaderQueries) {
        VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
        info.queryType = VK_QUERY_TYPE_MESH_PRIMITIVES_GENERATED_EXT;
        info.queryCount = 1;
        EXPECT_EQ(vkCreateQueryPool(device.handle(), &info, nullptr, &primitives), VK_SUCCESS);
        device.setName(VK_OBJECT_TYPE_QUERY_POOL, primitives, draw.name + ".primitivesQuery");
    }

    // Quads: MS_TASK_PATCHES patches a task workgroup; triangles: a group each.
    const uint32_t patchCount = uint32_t(draw.patches.size());
    const uint32_t taskGroups = draw.groups.empty() ? (patchCount + 31) / 32 : uint32_t(draw.groups.size());
    const Clock::time_point start = Clock::now();
    device.submitImmediate(
        [&](VkCommandBuffer cmd) {
            vkCmdFillBuffer(cmd, results.handle(), 0, VK_WHOLE_SIZE, 0);
            gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                               VK_PIPELINE_STAGE_2_MESH_SHADER_BIT_EXT,
                               VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
            if (primitives) vkCmdResetQueryPool(cmd, primitives, 0, 1);
            const float clear[4] = {0, 0, 0, 0};
            target.beginRendering(cmd, clear);
            const VkViewport viewport{0, 0, 1, 1, 0, 1};
            const VkRect2D scissor{{0, 0}, {1, 1}};
            vkCmdSetViewport(cmd, 0, 1, &viewport);
            vkCmdSetScissor(cmd, 0, 1, &scissor);
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline.handle());
            std::vector<std::pair<uint32_t, VkDescriptorBufferInfo>> bound = {
                {TS_CAPTURE_BINDING_RESULTS, {results.handle(), 0, VK_WHOLE_SIZE}},
                {TS_BINDING_MESH_KEYS, {keys.handle(), 0, VK_WHOLE_SIZE}},
                {TS_BINDING_MESH_TRIANGLES, {triangles.handle(), 0, VK_WHOLE_SIZE}},
                {TS_BINDING_MESH_PATCHES, {patches.handle(), 0, VK_WHOLE_SIZE}}};
            // The quad shaders read no groups, so their draw pushes none.
            if (groups.valid()) bound.push_back({TS_CAPTURE_BINDING_GROUPS, {groups.handle(), 0, VK_WHOLE_SIZE}});
            std::vector<VkWriteDescriptorSet> writes(bound.size(), {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET});
            for (size_t i = 0; i < bound.size(); ++i) {
                writes[i].dstBinding = bound[i].first;
                writes[i].descriptorCount = 1;
                writes[i].descriptorType = storage;
                writes[i].pBufferInfo = &bound[i].second;
            }
            device.fn().cmdPushDescriptorSet(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout.handle(), 0,
                                             uint32_t(writes.size()), writes.data());
            vkCmdPushConstants(cmd, layout.handle(), stages, 0, sizeof patchCount, &patchCount);
            if (primitives) vkCmdBeginQuery(cmd, primitives, 0, 0);
            device.fn().cmdDrawMeshTasks(cmd, taskGroups, 1, 1);
            if (primitives) vkCmdEndQuery(cmd, primitives, 0);
            target.endRendering(cmd);
            gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_MESH_SHADER_BIT_EXT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                               VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
        },
        draw.name.c_str());
    CaptureRun run;
    run.seconds = secondsSince(start);
    const auto* mapped = static_cast<const TsMeshCaptureResult*>(results.mapped());
    run.results.assign(mapped, mapped + patchCount);
    if (primitives) {
        uint64_t count = 0;
        EXPECT_EQ(vkGetQueryPoolResults(device.handle(), primitives, 0, 1, sizeof count, &count, sizeof count,
                                        VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
                  VK_SUCCESS);
        run.primitives = count;
        vkDestroyQueryPool(device.handle(), primitives, nullptr);
    }
    return run;
}

gpu::Device* meshDevice(std::string& skip) {
    std::string why;
    gpu::Device* device = GpuTestDevice::get(why);
    if (!device) {
        skip = why;
        return nullptr;
    }
    const device::DeviceFeatures& features = device->features();
    if (!features.meshShader || !device->fn().cmdDrawMeshTasks) {
        skip = features.deviceName + " has no task and mesh shaders";
        return nullptr;
    }
    // The pattern's largest piece must fit one workgroup (the Vulkan minimum
    // is 256 of each).
    if (features.maxMeshOutputVertices < TS_MESH_MAX_VERTICES ||
        features.maxMeshOutputPrimitives < TS_MESH_MAX_TRIANGLES) {
        skip = features.deviceName + " has smaller mesh outputs than one piece";
        return nullptr;
    }
    return device;
}

std::string describe(const TsMeshCaptureResult& r) {
    char text[96];
    std::snprintf(text, sizeof text, "%u triangles, hashes %08x %08x, %u workgroups", r.triangles, r.hashSum, r.hashXor,
                  r.workgroups);
    return text;
}

/// Compares every patch's digest with Tessellator's and the query with
/// countTriangles; `describePatch` names a patch's levels in a failure.
template <class Describe>
void expectCaptureMatches(const CaptureDraw& draw, const CaptureRun& run, Domain domain,
                          const std::vector<TessFactors>& levels, const std::vector<uint32_t>& pieces,
                          Describe&& describePatch) {
    ASSERT_EQ(run.results.size(), levels.size());
    const Clock::time_point start = Clock::now();
    uint64_t expectedTriangles = 0;
    uint32_t wrong = 0;
    for (size_t i = 0; i < levels.size(); ++i) {
        TsMeshCaptureResult expected = referenceDigest(domain, levels[i]);
        expected.workgroups = pieces[i];
        EXPECT_EQ(expected.triangles, Tessellator::countTriangles(domain, Partitioning::FractionalOdd, levels[i]));
        expectedTriangles += expected.triangles;
        const TsMeshCaptureResult& actual = run.results[i];
        const bool same = actual.triangles == expected.triangles && actual.hashSum == expected.hashSum &&
                          actual.hashXor == expected.hashXor && actual.workgroups == expected.workgroups;
        if (!same && ++wrong <= 20)
            ADD_FAILURE() << draw.name << " patch " << i << " (" << describePatch(levels[i]) << "): device "
                          << describe(actual) << ", Tessellator " << describe(expected);
    }
    EXPECT_EQ(wrong, 0u) << "of " << levels.size() << " patches differ";
    if (run.primitives) {
        EXPECT_EQ(*run.primitives, expectedTriangles) << "mesh primitives generated";
    }
    std::printf("[          ] %s: %zu patches, %llu triangles, query %s, draw %.2f s, reference %.2f s\n",
                draw.name.c_str(), levels.size(), static_cast<unsigned long long>(expectedTriangles),
                run.primitives ? std::to_string(*run.primitives).c_str() : "n/a", run.seconds, secondsSince(start));
}

/// A patch's levels to the last bit (a float step from a boundary shows).
std::string describeExactly(const TessFactors& f) {
    char text[160];
    std::snprintf(text, sizeof text, "outer %.9g %.9g %.9g %.9g inner %.9g %.9g", f.outer[0], f.outer[1], f.outer[2],
                  f.outer[3], f.inner[0], f.inner[1]);
    return text;
}

/// Levels where a point count changes: each odd integer, 1/256 and one
/// float step either side (none below 1).
std::vector<float> boundaryLevels() {
    const float nudge = 1.0f / 256.0f;
    std::vector<float> levels;
    for (int odd = 1; odd <= 63; odd += 2) {
        const float boundary = float(odd);
        for (float level : {boundary - nudge, std::nextafter(boundary, 0.0f), boundary,
                            std::nextafter(boundary, 100.0f), boundary + nudge})
            if (level >= 1.0f) levels.push_back(level);
    }
    return levels;
}

} // namespace

// Quads as the terrain draws them: the boundaries alone and mixed with other
// levels on the other edges and axis (ClassBoundariesMatchTheTessellator),
// then 2,000 random sets, a third of the levels exactly 1 or an odd integer.
TEST(MeshPatternCapture, QuadPatternsMatchTheTessellator) {
    std::string skip;
    gpu::Device* device = meshDevice(skip);
    if (!device) GTEST_SKIP() << skip;
    const uint64_t messagesBefore = GpuTestDevice::validationMessages();

    std::vector<TessFactors> levels;
    for (float level : boundaryLevels()) {
        levels.push_back({{level, level, level, level}, {level, level}});
        levels.push_back({{level, 1.0f, 64.0f, 7.0f}, {level, 3.0f}});
        levels.push_back({{2.0f, level, 9.0f, level}, {33.0f, level}});
    }
    const size_t boundaries = levels.size();
    Random rng(41u);
    auto pick = [&] {
        switch (rng.below(6)) {
        case 0:
            return 1.0f;
        case 1:
            return float(2 * rng.below(32) + 1);
        default:
            return rng.range(0.5f, TS_MESH_MAX_LEVEL);
        }
    };
    for (int i = 0; i < 2000; ++i) {
        TessFactors f;
        for (float& o : f.outer) o = pick();
        for (float& in : f.inner) in = pick();
        levels.push_back(f);
    }

    const MeshPatternLibrary& library = MeshPatternLibrary::quadFractionalOdd();
    CaptureDraw draw{"test.meshCaptureQuad",
                     mesh_capture_quad_task_spv,
                     mesh_capture_quad_mesh_spv,
                     library.keys(),
                     library.triangles(),
                     {},
                     {}};
    std::vector<uint32_t> pieces;
    for (const TessFactors& f : levels) {
        const glm::vec4 outer(f.outer[0], f.outer[1], f.outer[2], f.outer[3]);
        const glm::vec2 inner(f.inner[0], f.inner[1]);
        draw.patches.push_back({outer, glm::vec4(inner, 0.0f, 0.0f)});
        pieces.push_back(shader::tsMeshGroupCount(shader::tsMeshPatch(outer, inner)));
    }
    const CaptureRun run = runCapture(*device, draw);
    std::printf("[          ] %zu class-boundary patches, %zu random\n", boundaries, levels.size() - boundaries);
    expectCaptureMatches(draw, run, Domain::Quad, levels, pieces, describeExactly);
    EXPECT_EQ(GpuTestDevice::validationMessages(), messagesBefore) << "validation messages";
}

// Uniform-level triangles as characters draw them: the boundaries (and the
// clamped ends), each two patches in one task workgroup so the mesh stage's
// split of its workgroups between patches is exercised, then 2,000 random
// levels, a sixth exactly an odd integer, one patch a workgroup.
TEST(MeshPatternCapture, TrianglePatternsMatchTheTessellator) {
    std::string skip;
    gpu::Device* device = meshDevice(skip);
    if (!device) GTEST_SKIP() << skip;
    const uint64_t messagesBefore = GpuTestDevice::validationMessages();

    std::vector<float> boundaries = boundaryLevels();
    for (float level : {0.5f, 1.0f + 1.0f / 65536.0f, 1.0f + 1.0f / 131072.0f, 64.0f, 100.0f})
        boundaries.push_back(level);
    for (int even = 2; even <= 64; even += 2) boundaries.push_back(float(even));
    const MeshTrianglePatternLibrary& library = MeshTrianglePatternLibrary::uniformFractionalOdd();
    CaptureDraw draw{"test.meshCaptureTriangle",
                     mesh_capture_triangle_task_spv,
                     mesh_capture_triangle_mesh_spv,
                     library.keys(),
                     library.triangles(),
                     {},
                     {}};
    std::vector<float> levels;
    auto addGroup = [&](float level, uint32_t copies) {
        draw.groups.push_back({uint32_t(levels.size()), copies, 0, 0});
        for (uint32_t c = 0; c < copies; ++c) {
            levels.push_back(level);
            draw.patches.push_back({glm::vec4(level), glm::vec4(level)});
        }
    };
    for (float level : boundaries) addGroup(level, 2);
    Random rng(43u);
    for (int i = 0; i < 2000; ++i)
        addGroup(rng.below(6) == 0 ? float(2 * rng.below(32) + 1) : rng.range(1.0f, TS_MESH_MAX_LEVEL), 1);

    std::vector<TessFactors> factors;
    std::vector<uint32_t> pieces;
    for (float level : levels) {
        factors.push_back({{level, level, level, level}, {level, level}});
        pieces.push_back(shader::tsMeshTrianglePatch(level).pieceCount);
    }
    const CaptureRun run = runCapture(*device, draw);
    std::printf("[          ] %zu class-boundary patches (two a level), 2000 random\n", 2 * boundaries.size());
    expectCaptureMatches(draw, run, Domain::Triangle, factors, pieces, describeExactly);
    EXPECT_EQ(GpuTestDevice::validationMessages(), messagesBefore) << "validation messages";
}

// The digest's own negative control, on the CPU: a one-ulp move of one
// coordinate or the other winding changes a triangle's hashes, and the
// starting corner does not (both sides rotate before hashing).
TEST(MeshPatternCapture, DigestSeesOneUlpAndWinding) {
    const glm::vec2 a(0.25f, 0.5f), b(0.5f, 0.5f), c(0.25f, 0.75f);
    const glm::uvec2 h = shader::tsCaptureHashes(a, b, c);
    EXPECT_NE(h, shader::tsCaptureHashes(a, b, glm::vec2(c.x, std::nextafter(c.y, 1.0f))));
    EXPECT_NE(h, shader::tsCaptureHashes(a, c, b));
    EXPECT_NE(h.x, h.y);
    const PatternTriangle rotated = canonicalTriangle({{{b.x, b.y}, {c.x, c.y}, {a.x, a.y}}});
    EXPECT_EQ(h, shader::tsCaptureHashes({rotated[0][0], rotated[0][1]}, {rotated[1][0], rotated[1][1]},
                                         {rotated[2][0], rotated[2][1]}));
}
