#pragma once
/// @file TerrainTiles.h
/// The terrain's tiling as scene nodes: one node per tile, its bounds the
/// true displaced bounds of the tile (min/max height over its samples), so
/// frustum culling never drops a tile whose peak is in view.

#include "tessera/scene/Frustum.h"
#include "tessera/scene/NodeId.h"
#include "tessera/scene/SceneGraph.h"
#include "tessera/terrain/HeightField.h"

#include <cstdint>
#include <vector>

namespace tessera::terrain {

class TerrainTiles {
public:
    /// Scene-node kind tag for terrain tiles (SceneNode::kind).
    static constexpr uint32_t kNodeKind = 0x7E11u;

    /// Creates a root node "terrain" and tilesPerSide^2 child nodes in `scene`.
    TerrainTiles(scene::SceneGraph& scene, const HeightField& field, uint32_t tilesPerSide);

    uint32_t tilesPerSide() const { return mTilesPerSide; }
    uint32_t tileCount() const { return mTilesPerSide * mTilesPerSide; }
    /// World-space bounds of a tile.
    const scene::Aabb& tileBounds(uint32_t tile) const;
    scene::NodeId root() const { return mRoot; }

    /// Recomputes the bounds of the tiles overlapping the sample rectangle
    /// (after a deformation changed heights there).
    void refreshBounds(uint32_t i0, uint32_t j0, uint32_t i1, uint32_t j1);

    /// Appends the indices of tiles whose bounds intersect `frustum`, ordered
    /// near to far from `eye` so early depth rejects hidden fragments.
    void cull(const scene::Frustum& frustum, const glm::vec3& eye, std::vector<uint32_t>& visible) const;

private:
    void computeBounds(uint32_t tile);

    scene::SceneGraph& mScene;
    const HeightField& mField;
    uint32_t mTilesPerSide;
    scene::NodeId mRoot;
    std::vector<scene::NodeId> mNodes;
    mutable std::vector<scene::NodeId> mScratch;
};

} // namespace tessera::terrain
