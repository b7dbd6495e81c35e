#pragma once
/// @file FarMesh.h
/// The far LOD tier's mesh: a cage simplified to a few hundred triangles,
/// skinned by the same palette (same CageMesh::bindings), so the crowd can
/// draw distant instances with the pose it already computes for the cage.
/// Made at content build time by tessera-creaturegen (stored in the .glb as
/// an MSFT_lod level) and at load time for files without one.

#include "tessera/character/CageMesh.h"
#include "tessera/core/Result.h"

#include <cstdint>

namespace tessera::character {

/// What to make.
struct FarMeshSettings {
    /// Triangles to aim for. The result has at most this many, unless even
    /// the last resort (meshopt_simplifySloppy) cannot get there.
    uint32_t targetTriangles = 300;
    /// The largest simplification error allowed to the edge-collapse passes,
    /// relative to the cage's extent (meshoptimizer's measure: 0.05 is 5% of
    /// the largest bounding-box side). A pass that stops on this error
    /// before the target hands over to the next method.
    float maxError = 0.05f;
};

/// How the far mesh was made, from the most faithful method to the coarsest.
enum class FarMeshMethod : uint8_t {
    /// The cage already had no more than the target: copied (compacted).
    Copy,
    /// meshopt_simplify on the cage's own vertices: every UV seam is kept
    /// (seam copies collapse together), so no triangle spans two charts.
    SeamPreserving,
    /// meshopt_simplify on positions welded across UV seams: reaches the
    /// target where chart corners lock the seam-preserving pass; the surface
    /// stays closed (a collapse order that pinches a non-manifold edge is
    /// retried), but a triangle may span two charts (`seamTriangles`).
    Welded,
    /// meshopt_simplifySloppy (vertex clustering) on welded positions: the
    /// last resort; it may open holes or leave non-manifold edges.
    Sloppy,
};

/// The far mesh and what its simplification cost.
struct FarMesh {
    /// Only the vertices the triangles use, each a copy of a cage vertex
    /// (position, normal, tangent, uv, joints, weights), and the cage's
    /// `bindings` unchanged.
    CageMesh mesh;
    /// The same triangles as indices into the cage's own vertices (before
    /// `mesh` compacted them): a coarser index list over the cage, which the
    /// crowd's middle tier draws over the cage's baked vertices.
    std::vector<uint32_t> cageIndices;
    FarMeshMethod method = FarMeshMethod::Copy;
    /// meshoptimizer's error of the method used, relative to the cage's
    /// extent (0 for Copy; summed over the stages when the welded pass
    /// stopped at an intermediate target to avoid a pinch).
    float relativeError = 0.0f;
    /// The same in model units (relativeError times meshopt_simplifyScale).
    float absoluteError = 0.0f;
    /// Triangles whose corners come from more than one UV chart (Welded and
    /// Sloppy only): their uvs are the nearest the atlas offers, so the
    /// texture smears across them. Geometry and skinning are exact.
    uint32_t seamTriangles = 0;
};

/// Simplifies `cage` for the far tier with meshoptimizer. Deterministic: the
/// same cage and settings give the same mesh on every run and machine.
///
/// It tries, in order, until the result has at most
/// `settings.targetTriangles` triangles: the seam-preserving edge-collapse
/// pass, the welded edge-collapse pass (both bounded by `maxError`), then
/// vertex clustering. A closed cage (closed once welded by position) stays
/// closed through the first two.
///
/// Fails, with a one-line message, on a cage without triangles, an index
/// count that is not a multiple of 3, an index out of range, a non-finite
/// position, a target of zero or a negative or non-finite maximum error.
Result<FarMesh> simplifyCage(const CageMesh& cage, const FarMeshSettings& settings = {});

/// The name of a method, for reports ("seam-preserving", "welded", ...).
const char* farMeshMethodName(FarMeshMethod method);

} // namespace tessera::character
