#pragma once
/// @file FanResolutions.h
/// The level limits of non-uniform tiles (Niessner and Loop, section 4.4):
/// per fan (ptex vertex) the finest resolution every tile around it has,
/// in units shared across edges (log2 of texels per base edge: a tile's k,
/// plus 1 for a sub-face of a non-quad, half as wide along a base edge).
///
/// Why the smallest, not the paper's "highest resolution" as the vertex's
/// base value: a tile's limit is its k minus the bilinear interpolant of
/// its corner differences, so along an edge it is the linear interpolant of
/// the values at the edge's two ends, as each side computes them. Both sides
/// agree only if every tile around a vertex reaches the same value there,
/// and no tile may reach past its own k: the one value that works is the
/// smallest k around the vertex (differences k - base >= 0, one of them 0).
/// With the largest, a tile's value at the vertex would be 2k - base,
/// different for every size around it.
///
/// A T-junction adds a constraint: a quad's edge along an n-gon runs from
/// p to q through the midpoint m, where the sub-faces have corners and the
/// quad has none; the quad interpolates p and q linearly, the sub-faces
/// p-m and m-q, so the value at m must be the mean of p's and q's. Setting
/// all three to their minimum satisfies it; the minimum is propagated until
/// nothing changes.

#include "tessera/core/Result.h"
#include "tessera/subdiv/PtexTopology.h"

#include <cstdint>
#include <span>
#include <vector>

namespace tessera::subdiv::detail {

/// Per fan, the limit described above. Error: a fan whose limit is below
/// some tile's coarsest level (resolution 1, or 2 for a sub-face), which
/// happens only when a quad of k = 1 shares a vertex with a sub-face.
Result<std::vector<uint8_t>> fanResolutions(const PtexTopology& topology, std::span<const uint8_t> log2Size);

} // namespace tessera::subdiv::detail
