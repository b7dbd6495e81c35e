#pragma once
/// @file PatchData.h
/// The patches of a SubdivSurface as plain data a GPU consumes directly:
/// OpenSubdiv's patch types and packed patch parameters, without OpenSubdiv
/// headers. Every struct here is made of 4-byte scalars so it uploads as is
/// into a std430 storage buffer.

#include <cstdint>

namespace tessera::subdiv {

/// A patch's basis. The values are OpenSubdiv's Far::PatchDescriptor::Type
/// values, which are also the OSD_PATCH_DESCRIPTOR_* constants that
/// OsdEvaluatePatchBasis (GLSL) switches on: pass them to the shader as they
/// are.
enum class PatchType : uint32_t {
    /// Bicubic B-spline, 16 control points in row-major 4x4 order; on a
    /// boundary or infinitely sharp crease the boundary mask says which rows
    /// are phantoms (their indices are valid but their weights fold into
    /// the others).
    Regular = 6,
    /// Gregory basis end cap, 20 control points in OpenSubdiv's order (per
    /// corner: the point, the two edge points, the two face points).
    GregoryBasis = 9,
};

/// Control points per patch of a type.
constexpr uint32_t controlPointsOf(PatchType type) {
    return type == PatchType::GregoryBasis ? 20u : 16u;
}

/// A Far::PatchParam packed exactly as OpenSubdiv packs it, plus the
/// single-crease sharpness: the three words of GLSL's OsdPatchParam (ivec3,
/// sharpness as float bits), so a shader calls OpenSubdiv's patch
/// evaluation unchanged. The accessors decode the documented bit layout.
///
/// The patch covers the square [u(), u() + 1] x [v(), v() + 1] scaled by
/// paramFraction() of its ptex face: a quad base face, or one quad sub-face
/// of a non-quad base face (see FaceParameterization).
struct PatchParam {
    /// faceId (bits 0-27, the ptex face), transition mask (bits 28-31).
    uint32_t field0 = 0;
    /// depth (bits 0-3), non-quad root (4), regular (5), boundary mask
    /// (7-11), v (12-21), u (22-31).
    uint32_t field1 = 0;
    /// Single-crease sharpness; always 0 here (single-crease patches are off
    /// because OsdEvaluatePatchBasis ignores it).
    float sharpness = 0.0f;

    /// The ptex face the patch lies in (SubdivSurface::firstPtexFace).
    uint32_t ptexFace() const { return field0 & 0x0fffffffu; }
    /// Edges shared with patches one level deeper (bit e for patch edge e:
    /// 0 is v = 0, 1 is u = 1, 2 is v = 1, 3 is u = 0).
    uint32_t transitionMask() const { return field0 >> 28; }
    /// Refinement level of the patch (non-quad faces start at 1).
    uint32_t depth() const { return field1 & 0xfu; }
    /// True when the patch descends from a non-quad base face. Such a
    /// patch's positions take its ptex sub-face's [0, 1] coordinates, but
    /// OpenSubdiv's basis (Far::PatchTable::EvaluateBasis and GLSL
    /// OsdEvaluatePatchBasis alike) scales its derivatives by 2^depth,
    /// which makes them derivatives per Bfr's half-size tile: halve first
    /// derivatives (quarter second ones) for derivatives per ptex (u, v),
    /// as SubdivSurface's evaluation does.
    bool nonQuadRoot() const { return (field1 >> 4) & 1u; }
    /// True for a regular (B-spline) patch, false for an end cap.
    bool isRegular() const { return (field1 >> 5) & 1u; }
    /// Boundary or infinitely sharp edges, encoded like transitionMask().
    uint32_t boundaryMask() const { return (field1 >> 7) & 0x1fu; }
    /// The patch's column at its depth within the ptex face.
    uint32_t u() const { return field1 >> 22; }
    /// The patch's row at its depth within the ptex face.
    uint32_t v() const { return (field1 >> 12) & 0x3ffu; }
    /// Edge length of the patch in ptex-face coordinates.
    double paramFraction() const { return 1.0 / double(1u << (depth() - (nonQuadRoot() ? 1u : 0u))); }
};

/// One patch: its type, where its control-point indices start in
/// SubdivSurface::patchPointIndices(), and its parameters.
struct Patch {
    PatchType type = PatchType::Regular;
    /// Index of the first of controlPointsOf(type) entries in
    /// patchPointIndices().
    uint32_t firstIndex = 0;
    PatchParam param;
};

/// A run of consecutive patches of one type (OpenSubdiv's patch array):
/// one tessellation draw, whose patch control-point count is fixed.
struct PatchRange {
    PatchType type = PatchType::Regular;
    uint32_t firstPatch = 0;
    uint32_t patchCount = 0;
    /// Index of the range's first entry in patchPointIndices().
    uint32_t firstIndex = 0;
};

} // namespace tessera::subdiv
