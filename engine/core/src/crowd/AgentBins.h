#pragma once
// Internal: agents binned by navigation tile, with a bounds pyramid over the
// tiles: the crowd's bounds hierarchy (for culling) and the density splat's
// unit of work.

#include "tessera/crowd/NavGrid.h"
#include "tessera/scene/Aabb.h"
#include "tessera/scene/Frustum.h"

#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

namespace tessera::crowd {

/// Level 0 holds one box per tile (its agents' boxes); each level above
/// merges 2 x 2 boxes of the one below, up to a single root. Culling walks
/// down from the root, takes whole subtrees that are inside the frustum
/// without further tests, and skips subtrees outside, as Terrain::cull does
/// with the terrain's min/max pyramid.
class AgentBins {
public:
    explicit AgentBins(const NavGrid& grid);

    /// Bins every agent by the tile under it (clamped to the grid), in
    /// ascending index order within a tile, and rebuilds the boxes: an agent
    /// is a box of its radius around its position, `height` metres tall.
    void build(std::span<const glm::vec3> positions, std::span<const float> radius, float height, uint32_t threads);

    std::span<const uint32_t> agentsIn(uint32_t tile) const {
        return {mAgents.data() + mStart[tile], mStart[tile + 1] - mStart[tile]};
    }
    /// Every agent, grouped by tile in tile order.
    std::span<const uint32_t> order() const { return mAgents; }
    /// Per tile, where its agents begin in order(); one more at the end.
    std::span<const uint32_t> starts() const { return mStart; }
    /// Tiles holding at least one agent, ascending.
    std::span<const uint32_t> occupiedTiles() const { return mOccupied; }
    /// Every agent's box together (empty without agents).
    const scene::Aabb& bounds() const { return mLevels.back().front(); }
    /// Appends the agents whose tile's box is not outside `frustum` (a
    /// conservative superset of the visible agents), tile by tile.
    void cull(const scene::Frustum& frustum, std::vector<uint32_t>& out) const;
    /// Bytes that grow with the agents, and with the tiles.
    size_t agentBytes() const;
    size_t tileBytes() const;

private:
    void cullNode(const scene::Frustum& frustum, uint32_t level, uint32_t x, uint32_t z, bool inside,
                  std::vector<uint32_t>& out) const;

    const NavGrid& mGrid;
    std::vector<uint32_t> mStart;    ///< tile -> first agent slot; one extra at the end
    std::vector<uint32_t> mAgents;   ///< agents, grouped by tile
    std::vector<uint32_t> mTileOf;   ///< agent -> tile (build scratch)
    std::vector<uint32_t> mOccupied;
    std::vector<std::vector<scene::Aabb>> mLevels;
    std::vector<uint32_t> mLevelWidth, mLevelHeight;
};

} // namespace tessera::crowd
