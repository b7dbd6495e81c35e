#pragma once
// The high-resolution sculpt (internal header).

#include "CreatureSdf.h"
#include "IndexedMesh.h"
#include "SkinDetail.h"
#include "creature/SculptMesh.h"

#include <functional>

namespace tessera::creature {

/// Splits every cage triangle into four (shared edge midpoints, so the
/// result stays watertight) until there are at least `minTriangles`, then
/// moves each vertex onto the base shape with Newton steps along the
/// field's gradient and out along the normal by the skin detail. Every
/// vertex ends within a few centimetres of the cage surface, along the
/// cage normal's neighbourhood, as the baker's envelopes require.
SculptMesh makeSculpt(const IndexedMesh& cage, const CreatureSdf& sdf, const SkinDetail& skin, uint32_t minTriangles,
                      const std::function<void(float)>& progress = {});

} // namespace tessera::creature
