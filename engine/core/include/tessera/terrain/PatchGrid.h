#pragma once
/// @file PatchGrid.h
/// The terrain's control mesh: P x P square superprimitive patches over the
/// height field, and the canonical numbering of their edges.

#include "tessera/scene/Aabb.h"
#include "tessera/terrain/HeightField.h"
#include "tessera/terrain/SampleRect.h"

#include <array>
#include <cstdint>

#include <glm/vec2.hpp>

namespace tessera::terrain {

/// Geometry and numbering of the control mesh, identical to the shaders'
/// (engine/core/include/tessera/shaders/TerrainPatches.h, which this class calls):
/// patch (x, z) has index z * P + x and covers world X in
/// [x, x+1] * patchSize().x and Z in [z, z+1] * patchSize().y. Each edge is
/// numbered once, in a canonical direction, so neighbours share its
/// tessellation factor. Patches need not align with samples.
class PatchGrid {
public:
    /// `patchesPerSide` >= 1. Keeps a reference to `field` for sample ranges.
    PatchGrid(const HeightField& field, uint32_t patchesPerSide);

    uint32_t patchesPerSide() const { return mPatchesPerSide; }
    uint32_t patchCount() const { return mPatchesPerSide * mPatchesPerSide; }
    /// 2 * P * (P + 1): edges along X, then edges along Z.
    uint32_t edgeCount() const;
    /// World size of one patch along X and Z (metres).
    glm::vec2 patchSize() const { return mPatchSize; }

    /// World XZ of the patch's lowest corner.
    glm::vec2 patchOrigin(uint32_t patch) const;
    /// The patch's four edges in Vulkan quad outer-level order
    /// ([0] u=0 / -X side, [1] v=0 / -Z side, [2] u=1 / +X side, [3] v=1 / +Z side).
    std::array<uint32_t, 4> patchEdges(uint32_t patch) const;
    /// World XZ of an edge's endpoints in canonical order (increasing X or Z).
    std::array<glm::vec2, 2> edgeEndpoints(uint32_t edge) const;

    /// Inclusive range of samples the surface over the patch interpolates
    /// between (floor of its lower corner to ceil of its upper corner).
    SampleRect patchSamples(uint32_t patch) const;
    /// Patch index range [x0, x1] x [z0, z1] (as a SampleRect of patch
    /// coordinates) of every patch whose surface depends on a sample in `samples`.
    SampleRect patchesTouching(const SampleRect& samples) const;

private:
    const HeightField& mField;
    uint32_t mPatchesPerSide;
    glm::vec2 mPatchSize;
};

} // namespace tessera::terrain
