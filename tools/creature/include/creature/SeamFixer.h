#pragma once
/// @file SeamFixer.h
/// Makes both sides of every UV seam fetch the same displacement (the
/// paper's Figure 17 crack fix, done in the baker instead of the shader).

#include "tessera/character/CageMesh.h"

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace tessera::creature {

/// Finds the cage's UV seams (edges whose two triangles, welded by position,
/// place the edge's endpoints at different UVs, and vertices that appear at
/// two or more UVs) and reconciles the texels along them.
///
/// Each seam edge is sampled at evenly spaced parameters in both charts; a
/// sample pair asks that the two bilinear fetches (the renderer's filter)
/// agree. fix() solves all pairs together in the least-squares sense with
/// the smallest change to the texels, so both sides meet near their mean.
/// Seam vertices add one pair per extra chart meeting there.
class SeamFixer {
public:
    SeamFixer(const character::CageMesh& cage, uint32_t size);

    uint64_t seamEdgeCount() const { return mEdges.size(); }
    uint64_t seamVertexCount() const { return mVertexPairs.size(); }

    /// Largest |fetch(side A) - fetch(side B)| over all seam vertices and over
    /// seam edges sampled `perTexel` times per texel of edge length.
    float maxMismatch(const std::vector<float>& map, float perTexel) const;
    /// The same differences one by one: seam vertices first, then each seam
    /// edge's interior samples in edge order (for diagnostics).
    std::vector<float> mismatches(const std::vector<float>& map, float perTexel) const;

    /// Moves the texels under the seams' fetches by the least-squares change
    /// of least norm that makes the pairs (`perTexel` per texel of edge
    /// length) agree: conjugate gradients on the normal equations (CGLS), at
    /// most `iterations` steps, stopping once every pair agrees within
    /// `tolerance`. Sets fixed[i] = 1 for every texel it changes and returns
    /// how many texels that is.
    uint64_t fix(std::vector<float>& map, std::vector<uint8_t>& fixed, float perTexel, uint32_t iterations,
                 float tolerance) const;

private:
    struct SeamEdge {
        glm::vec2 a0, a1;  ///< the edge in one chart
        glm::vec2 b0, b1;  ///< the same edge, same direction, in the other
    };
    struct SeamPair {
        glm::vec2 a, b;
    };

    std::vector<SeamPair> pairs(float perTexel) const;

    uint32_t mSize;
    std::vector<SeamEdge> mEdges;
    std::vector<SeamPair> mVertexPairs;
};

} // namespace tessera::creature
