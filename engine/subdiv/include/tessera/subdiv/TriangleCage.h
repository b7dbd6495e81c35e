#pragma once
/// @file TriangleCage.h
/// A character's triangle cage as a Catmull-Clark control mesh: the cage's
/// vertices are split along UV seams (one per chart), a subdivision control
/// mesh must not be, so positions that are bit-identical are welded into
/// one control vertex. Catmull-Clark on the welded triangles splits every
/// face into three quad sub-faces (three ptex faces a triangle), which
/// SubdivSurface, PtexTopology and DisplacementTiles handle.
///
/// The tool that bakes a character's tiles and the demo that draws them both
/// weld the cage they read from the same .glb through this one function, so
/// the control vertex numbering, and with it the ptex numbering the tiles are
/// laid out in, is the same on both sides; `topologyHash` lets a tile file
/// check that it was baked for this very control mesh.

#include "tessera/core/Result.h"
#include "tessera/subdiv/ObjShape.h"

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace tessera::subdiv {

struct WeldedCage {
    /// The control mesh: one triangle per cage triangle, welded positions
    /// (numbered by first use in the cage's vertex order), boundaries
    /// interpolated (edges and corners) should the cage be open.
    ObjShape shape;
    /// Per cage vertex, its control vertex.
    std::vector<uint32_t> controlOf;
    /// Per control vertex, the first cage vertex welded into it (the one
    /// whose skinning the animated control vertex takes: welded vertices
    /// share position and skinning, docs/CHARACTERS.md).
    std::vector<uint32_t> firstCageVertex;
    /// FNV-1a over the control vertex count and the faces' control indices.
    uint64_t topologyHash = 0;
};

/// Welds `positions` (the cage's vertices) and `indices` (three per
/// triangle) into a control mesh named `name`. Errors, naming `name`: no
/// triangles, an index count not a multiple of 3, an index out of range, a
/// non-finite position, a triangle whose corners weld into fewer than three
/// control vertices (degenerate: Catmull-Clark cannot refine it).
Result<WeldedCage> weldTriangleCage(std::span<const glm::vec3> positions, std::span<const uint32_t> indices,
                                    const std::string& name);

} // namespace tessera::subdiv
