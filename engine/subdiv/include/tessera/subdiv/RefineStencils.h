#pragma once
/// @file RefineStencils.h
/// The linear map from a control mesh's base vertices to every control point
/// of its patches, as plain arrays a GPU applies each frame to animate the
/// surface (one weighted sum per point).

#include <cstdint>
#include <vector>

namespace tessera::subdiv {

/// One stencil per control point (SubdivSurface::controlPoints() order):
/// point i = sum over k < sizes[i] of weights[offsets[i] + k] times base
/// vertex indices[offsets[i] + k]. Base vertices come first with one entry
/// of weight 1 each, so one pass writes every point.
struct RefineStencils {
    std::vector<uint32_t> offsets;
    std::vector<uint32_t> sizes;
    std::vector<uint32_t> indices;
    std::vector<float> weights;

    uint32_t pointCount() const { return uint32_t(sizes.size()); }
    uint32_t entryCount() const { return uint32_t(indices.size()); }
};

} // namespace tessera::subdiv
