#pragma once
/// @file TerrainDetail.h
/// How far the height field strays from each untessellated edge and patch:
/// the input of the height-map detail tessellation metric.

#include "tessera/terrain/PatchGrid.h"

#include <vector>

namespace tessera::terrain {

/// Geometric error, in metres, of the control mesh against the height field.
///  - edgeError()[e]: the largest |h(t) - lerp(h(a), h(b), t)| over points
///    one sample spacing apart along edge e (PatchGrid numbering), i.e. how
///    far the straight edge cuts through or floats above the terrain;
///  - patchError()[p]: the largest |h - bilinear(corner heights)| over the
///    patch's interior on the same spacing.
/// Flat or planar ground has error 0 and stays at the minimum level; ridges
/// and craters get many triangles. Recomputed locally after splats, so the
/// metric follows deformation in the same frame.
class TerrainDetail {
public:
    TerrainDetail(const HeightField& field, const PatchGrid& grid);

    const std::vector<float>& edgeError() const { return mEdgeError; }
    const std::vector<float>& patchError() const { return mPatchError; }

    /// Recomputes the patches in the inclusive patch rectangle and all their edges.
    void update(const SampleRect& patches);

private:
    float computeEdge(uint32_t edge) const;
    float computePatch(uint32_t patch) const;

    const HeightField& mField;
    const PatchGrid& mGrid;
    std::vector<float> mEdgeError;
    std::vector<float> mPatchError;
};

} // namespace tessera::terrain
