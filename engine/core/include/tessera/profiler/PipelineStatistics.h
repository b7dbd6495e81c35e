#pragma once
/// @file PipelineStatistics.h
/// The Vulkan pipeline-statistics counters of one GPU pass, and the mesh
/// primitives generated, CPU-side.
///
/// Field for field this is VkQueryPipelineStatisticFlagBits (core Vulkan 1.0,
/// and VK_EXT_mesh_shader's task and mesh invocations) minus the Vulkan
/// types, so tessera_core stays free of Vulkan. The Vulkan layer fills it
/// from a VK_QUERY_TYPE_PIPELINE_STATISTICS query; counters a device does
/// not support stay 0.

#include <cstdint>

namespace tessera::profiler {

struct PipelineStatistics {
    uint64_t inputAssemblyVertices = 0;
    /// Primitives read by input assembly: patches when the pass tessellates.
    uint64_t inputAssemblyPrimitives = 0;
    uint64_t vertexShaderInvocations = 0;
    uint64_t geometryShaderInvocations = 0;
    uint64_t geometryShaderPrimitives = 0;
    /// Primitives entering the clipper (after tessellation and geometry shading).
    uint64_t clippingInvocations = 0;
    /// Primitives leaving the clipper: the ones that can reach the rasterizer.
    uint64_t clippingPrimitives = 0;
    uint64_t fragmentShaderInvocations = 0;
    uint64_t tessControlPatches = 0;
    uint64_t tessEvaluationInvocations = 0;
    uint64_t computeShaderInvocations = 0;
    /// Task (amplification) and mesh shader invocations; Vulkan lets a
    /// device count a workgroup once or per invocation (lavapipe: per
    /// invocation), so compare them on one device only.
    uint64_t taskShaderInvocations = 0;
    uint64_t meshShaderInvocations = 0;
    /// Primitives the mesh shaders emitted (VK_EXT_mesh_shader's own query,
    /// not a pipeline statistic): a mesh pass's triangles before clipping,
    /// as clippingInvocations are a tessellating pass's.
    uint64_t meshPrimitivesGenerated = 0;
};

/// Calls `fn(name, memberPointer)` for every counter in declaration order, so
/// writers and arithmetic cannot miss a field. `name` is the field's name.
template <class Fn>
constexpr void forEachPipelineStatistic(Fn&& fn) {
    using S = PipelineStatistics;
    fn("inputAssemblyVertices", &S::inputAssemblyVertices);
    fn("inputAssemblyPrimitives", &S::inputAssemblyPrimitives);
    fn("vertexShaderInvocations", &S::vertexShaderInvocations);
    fn("geometryShaderInvocations", &S::geometryShaderInvocations);
    fn("geometryShaderPrimitives", &S::geometryShaderPrimitives);
    fn("clippingInvocations", &S::clippingInvocations);
    fn("clippingPrimitives", &S::clippingPrimitives);
    fn("fragmentShaderInvocations", &S::fragmentShaderInvocations);
    fn("tessControlPatches", &S::tessControlPatches);
    fn("tessEvaluationInvocations", &S::tessEvaluationInvocations);
    fn("computeShaderInvocations", &S::computeShaderInvocations);
    fn("taskShaderInvocations", &S::taskShaderInvocations);
    fn("meshShaderInvocations", &S::meshShaderInvocations);
    fn("meshPrimitivesGenerated", &S::meshPrimitivesGenerated);
}
// A field added above without adding it to forEachPipelineStatistic fails here.
static_assert(sizeof(PipelineStatistics) == 14 * sizeof(uint64_t),
              "update forEachPipelineStatistic() with the new counter");

/// Adds every counter of `rhs` to `lhs` (summing passes into a frame).
constexpr PipelineStatistics& operator+=(PipelineStatistics& lhs, const PipelineStatistics& rhs) {
    forEachPipelineStatistic([&](const char*, uint64_t PipelineStatistics::*field) {
        lhs.*field += rhs.*field;
    });
    return lhs;
}

/// The "triangles" figure Tessera reports for a pass (trace counter, benchmark
/// table): primitives that survived clipping, i.e. roughly what was sent to the
/// rasterizer after tessellation.
///
/// - `clippingPrimitives` when nonzero.
/// - Otherwise `inputAssemblyPrimitives`, for devices or passes that report no
///   clipping counts, but only when the pass neither tessellates nor runs a
///   geometry shader: then input-assembly primitives *are* the triangles. With
///   tessellation they are patches, and counting patches as triangles would
///   be off by the tessellation factor, so such a pass reports 0 (everything
///   clipped or culled).
/// - Compute passes, and passes whose primitives never reach the clipper
///   (rasterizer discard: transform-feedback and stream-out passes), report 0:
///   their input points are data, not triangles.
/// Primitives a pass generated for the clipper (the tessellator's or the mesh
/// shaders' triangles, before clipping and culling): clippingInvocations, or,
/// for a mesh-shader pass on a device that counts none there (lavapipe), the
/// mesh primitives generated. The backends' "same triangles" comparisons use it.
constexpr uint64_t generatedPrimitivesOf(const PipelineStatistics& s) {
    return s.clippingInvocations != 0 ? s.clippingInvocations : s.meshPrimitivesGenerated;
}

constexpr uint64_t trianglesOf(const PipelineStatistics& s) {
    if (s.clippingPrimitives != 0) return s.clippingPrimitives;
    if (s.clippingInvocations == 0 && s.fragmentShaderInvocations == 0) return 0;
    bool amplified = s.tessControlPatches != 0 || s.tessEvaluationInvocations != 0 ||
                     s.geometryShaderInvocations != 0;
    return amplified ? 0 : s.inputAssemblyPrimitives;
}

} // namespace tessera::profiler
