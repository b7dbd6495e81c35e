#pragma once
// Per-vertex tangent frames from UV derivatives (internal header).

#include "tessera/character/CageMesh.h"

namespace tessera::creature {

/// Sets every vertex's tangent to the area-weighted sum of its triangles'
/// dP/du, made orthogonal to the vertex normal and unit length; w = +1
/// (the atlas has no mirrored charts). Vertices whose sum degenerates get
/// any unit vector orthogonal to the normal.
void computeTangents(character::CageMesh& cage);

} // namespace tessera::creature
