#pragma once
/// @file FaceParameterization.h
/// How a base face's own (u, v) (OpenSubdiv Bfr's parameterization) maps to
/// the ptex faces Far's patches are parameterized over, without OpenSubdiv.
///
/// Quads: one ptex face; Bfr's (u, v) is the ptex (u, v): (0, 0) at face
/// vertex 0, u towards vertex 1, v towards vertex 3.
///
/// An n-gon (n != 4) is split once into n quad sub-faces, ptex faces
/// firstPtexFace + k for k = 0 .. n-1. Sub-face k has (s, t) = (0, 0) at
/// face vertex k, s towards the midpoint of edge (k, k+1), t towards the
/// midpoint of edge (k-1, k), and (1, 1) at the face centre; Far's patches
/// of the face carry PatchParam::nonQuadRoot() and start at depth 1.
/// Bfr lays these sub-faces out as tiles of a grid, w = ceil(sqrt(n))
/// tiles a row: sub-face k is the half-size square at (k mod w, k div w),
/// so (u, v) = (k mod w, k div w) + (s, t) / 2, and derivatives with respect
/// to Bfr's (u, v) are twice those with respect to the sub-face's (s, t).
/// The tests check this against Bfr::Parameterization for every face size
/// and against Bfr's limit surface.

#include <cstdint>

#include <glm/glm.hpp>

namespace tessera::subdiv {

/// A location in one ptex sub-face of a base face.
struct SubFaceCoord {
    uint32_t subFace = 0; ///< 0 for a quad; k (the corner vertex) for an n-gon
    glm::dvec2 st{0.0};   ///< in [0, 1]^2 of that ptex face
};

/// Conversions between a Catmull-Clark base face's Bfr (u, v) and its ptex
/// sub-faces (see the file comment).
class FaceParameterization {
public:
    /// A face of `faceSize` vertices (>= 3).
    explicit FaceParameterization(uint32_t faceSize);

    uint32_t faceSize() const { return mFaceSize; }
    /// True for non-quads, which are split into faceSize() sub-faces.
    bool hasSubFaces() const { return mFaceSize != 4; }
    /// Sub-face tiles per row of Bfr's layout (ceil(sqrt(n)); 1 for a quad).
    uint32_t tilesPerRow() const { return mTilesPerRow; }
    /// d(s, t) / d(u, v): 2 for sub-faces (half-size tiles), 1 for a quad.
    double derivativeScale() const { return hasSubFaces() ? 2.0 : 1.0; }

    /// The sub-face holding Bfr's (u, v), and its (s, t). A coordinate a
    /// little past a tile's half-size square (up to 3/4 of the tile, as
    /// Bfr rounds) belongs to that tile, clamped onto its square.
    SubFaceCoord toSubFace(glm::dvec2 uv) const;
    /// Bfr's (u, v) of a sub-face location.
    glm::dvec2 fromSubFace(const SubFaceCoord& coord) const;
    /// Bfr's (u, v) of face vertex `k`.
    glm::dvec2 vertexCoord(uint32_t k) const;
    /// Bfr's (u, v) of the face centre: the middle of a quad, the (1, 1)
    /// corner of sub-face 0 otherwise; (0.5, 0.5) either way.
    glm::dvec2 centerCoord() const { return glm::dvec2(0.5); }

private:
    uint32_t mFaceSize = 4;
    uint32_t mTilesPerRow = 1;
};

} // namespace tessera::subdiv
