#pragma once
// Turns the extracted iso-surface into the control cage's welded geometry
// (internal header).

#include "IndexedMesh.h"

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace tessera::creature {

/// Drops every connected component but the one with the most triangles
/// (stray specks where thin parts graze the grid) and unused vertices.
IndexedMesh keepLargestComponent(const IndexedMesh& mesh);

/// Simplifies a closed mesh to about `targetTriangles` with meshoptimizer's
/// edge collapses (which keep original vertex positions), then drops
/// unused vertices.
IndexedMesh simplifyMesh(const IndexedMesh& mesh, uint32_t targetTriangles);

/// Counts edges not shared by exactly two triangles in opposite directions
/// (0 for a closed, oriented 2-manifold) plus degenerate triangles.
size_t countTopologyDefects(const IndexedMesh& mesh);

/// Smooth unit vertex normals: the area-weighted sum of the adjacent
/// triangles' normals.
std::vector<glm::vec3> areaWeightedNormals(const IndexedMesh& mesh);

} // namespace tessera::creature
