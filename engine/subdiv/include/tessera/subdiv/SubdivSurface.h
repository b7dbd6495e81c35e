#pragma once
/// @file SubdivSurface.h
/// A Catmull-Clark base surface as patches (Niessner and Loop 2013, the base
/// surface of analytic displacement mapping): OpenSubdiv's feature-adaptive
/// refinement of an ObjShape into regular B-spline patches and end caps,
/// the control points and packed patch parameters a GPU tessellation
/// needs, animation by re-running precomputed stencils, and CPU
/// evaluation of positions and derivatives through Far's patch table.
///
/// OpenSubdiv stays behind a pimpl: including this header needs glm only.
/// The CPU reference it is checked against (Bfr) is BfrReference.h.

#include "tessera/core/Result.h"
#include "tessera/scene/Aabb.h"
#include "tessera/subdiv/LimitPoint.h"
#include "tessera/subdiv/ObjShape.h"
#include "tessera/subdiv/PatchData.h"
#include "tessera/subdiv/RefineStencils.h"
#include "tessera/subdiv/SubdivSettings.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>

#include <glm/glm.hpp>

namespace tessera::subdiv {

/// The limit surface of a control mesh as OpenSubdiv patches.
///
/// Control points: one array, controlPoints(), laid out as OpenSubdiv's
/// patch table indexes it: the base vertices, then the vertices of every
/// adaptive refinement level in order (refinedVertexCount() in all), then
/// the end caps' local points (localPointCount()). Every patch's indices
/// point into it, so a GPU needs this one buffer, the index buffer and the
/// per-patch parameters, and nothing else.
///
/// Parameterization: patches live in ptex faces (one per quad base face,
/// n per n-gon; see FaceParameterization for the layout and Bfr's
/// correspondence). Evaluation results come with derivatives in the
/// coordinates the call takes (ptex (u, v) for evaluatePatch and
/// evaluatePtex, Bfr's face (u, v) for evaluateFace).
///
/// Derivatives: exact for B-spline patches. On Gregory end caps they are
/// OpenSubdiv's approximation (the derivatives of the Bezier patch whose
/// interior points are the face points blended at (u, v), as its GPU
/// shaders compute them), up to a few percent off the derivative of the
/// rational patch; Bfr uses the same, so normals agree with it.
///
/// Watertightness (measured in tests/subdiv/watertight_test.cpp): where two
/// patches share an edge, positions evaluated from either side in double
/// are bit-identical between Gregory end caps (shared edge points), and
/// between B-spline patches of one depth up to the order of summation
/// (1e-16 of the diagonal); between depths and between a B-spline patch
/// and an end cap they differ by 1e-8 .. 1e-7 of the diagonal, because each
/// side reads its own float control points (another level's vertices, or
/// local points), equal only in exact arithmetic. A crack-free GPU
/// tessellation must therefore not rely on bit-equal edge positions there.
///
/// Thread safety: const members may be called concurrently; create and
/// updateControlPoints need exclusive access.
class SubdivSurface {
public:
    /// Builds the patches of `shape` (Catmark scheme with the shape's
    /// boundary interpolation, creases, corners, holes and triangle rule).
    /// Errors, one line naming the shape: a face with fewer than 3 or more
    /// than kMaxFaceVertices vertices, an index out of range, inconsistent
    /// face arrays, a non-finite position or sharpness, or any topology
    /// OpenSubdiv rejects (its message, e.g. a crease on a missing edge, no
    /// vertices, no faces, a vertex of too high valence).
    static Result<SubdivSurface> create(const ObjShape& shape, const SubdivSettings& settings = {});

    SubdivSurface(SubdivSurface&&) noexcept;
    SubdivSurface& operator=(SubdivSurface&&) noexcept;
    ~SubdivSurface();

    /// The shape's name (for messages).
    const std::string& name() const;
    const SubdivSettings& settings() const;

    /// Base (control mesh) vertices and faces, as in the shape.
    uint32_t baseVertexCount() const;
    uint32_t baseFaceCount() const;
    /// Vertices of base face `face`.
    uint32_t baseFaceSize(uint32_t face) const;
    /// True for faces tagged as holes (no patches, no limit surface).
    bool isHole(uint32_t face) const;
    /// The current base positions (the shape's, or the last update's).
    std::span<const glm::vec3> basePositions() const;

    /// Every control point (see the class comment for the layout).
    std::span<const glm::vec3> controlPoints() const;
    /// Base plus refined vertices: the index of the first local point.
    uint32_t refinedVertexCount() const;
    /// End-cap local points, after the refined vertices.
    uint32_t localPointCount() const;
    /// Deepest adaptive refinement level reached.
    uint32_t maxDepth() const;

    /// Every patch, grouped by type as patchRanges() lists them.
    std::span<const Patch> patches() const;
    /// Control-point indices of every patch, patch after patch.
    std::span<const uint32_t> patchPointIndices() const;
    /// The control-point indices of one patch.
    std::span<const uint32_t> patchPoints(uint32_t patch) const;
    /// Runs of patches of one type (one draw each).
    std::span<const PatchRange> patchRanges() const;

    /// Ptex faces in all (quads count one, n-gons n).
    uint32_t ptexFaceCount() const;
    /// The ptex face of base face `face`'s sub-face 0.
    uint32_t firstPtexFace(uint32_t face) const;

    /// Bounding box of the control points the patches use; it contains the
    /// limit surface (the bases are convex combinations on their domains).
    scene::Aabb bounds() const;
    /// Length of bounds()' diagonal, the scale of relative tolerances.
    double boundsDiagonal() const;

    /// Recomputes the control points from new base positions (animation):
    /// one application of a stencil table precomputed at creation, mapping
    /// base vertices to every refined vertex and local point. Error: a
    /// count different from baseVertexCount() or a non-finite position.
    Status updateControlPoints(std::span<const glm::vec3> basePositions);
    /// The stencils updateControlPoints applies, for a GPU that refines
    /// the control points itself (factorized to base vertices, identity
    /// rows for the base vertices first).
    RefineStencils refineStencils() const;

    /// Evaluates patch `patch` (< patches().size()) at its own (s, t) in
    /// [0, 1]^2 (a tessellator's domain coordinate); derivatives are with
    /// respect to the patch's ptex-face (u, v), so they agree across
    /// patches of different depths.
    LimitPoint evaluatePatch(uint32_t patch, glm::dvec2 st) const;
    /// Evaluates ptex face `ptexFace` at (u, v) in [0, 1]^2, finding the
    /// patch with Far's PatchMap; nothing for a hole or a face without
    /// limit surface.
    std::optional<LimitPoint> evaluatePtex(uint32_t ptexFace, glm::dvec2 uv) const;
    /// Evaluates base face `face` at (u, v) in Bfr's parameterization of
    /// the face (FaceParameterization), derivatives with respect to it, so
    /// the result compares directly with BfrReference::evaluate.
    std::optional<LimitPoint> evaluateFace(uint32_t face, glm::dvec2 uv) const;
    /// The patch holding ptex (u, v) of `ptexFace`, if any.
    std::optional<uint32_t> findPatch(uint32_t ptexFace, glm::dvec2 uv) const;

private:
    friend class BfrReference;
    struct Impl;
    explicit SubdivSurface(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> mImpl;
};

} // namespace tessera::subdiv
