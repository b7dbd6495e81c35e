#pragma once
// Iso-surface extraction by marching tetrahedra (internal header).

#include "IndexedMesh.h"

#include <functional>
#include <glm/glm.hpp>

namespace tessera::creature {

/// Extracts the zero set of `field` (negative inside) over the box
/// [lo, hi] on a grid of spacing `cell`. Each cube is split into the six
/// tetrahedra of its Kuhn triangulation, which neighbouring cubes share
/// face for face, so the result is a closed, consistently oriented
/// 2-manifold (possibly several components). Vertices on the same grid edge
/// are shared. `field` is sampled from several threads.
///
/// The grid is sampled coarsely first: blocks whose corner distances are
/// all far from zero (the field is close to a distance) take the sign of
/// their corners without being sampled finely.
IndexedMesh marchTetrahedra(const std::function<float(const glm::vec3&)>& field, const glm::vec3& lo,
                            const glm::vec3& hi, float cell, const std::function<void(float)>& progress = {});

} // namespace tessera::creature
