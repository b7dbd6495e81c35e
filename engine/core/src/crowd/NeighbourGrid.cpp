#include "NeighbourGrid.h"

#include "tessera/core/ParallelFor.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace tessera::crowd {

void NeighbourGrid::build(std::span<const glm::vec3> positions, const TileAgents& tiles, float cellSize,
                          uint32_t threads) {
    mInverseCell = 1.0f / tiles.cellSize;
    mTileSize = float(tiles.tileCells) * tiles.cellSize;
    mWidth = tiles.width;
    mHeight = tiles.height;
    mTileCells = tiles.tileCells;
    mTilesX = (mWidth + mTileCells - 1) / mTileCells;
    mTilesZ = (mHeight + mTileCells - 1) / mTileCells;
    mTiles.assign(size_t(mTilesX) * mTilesZ, TileCells{});
    // Cells per side: as many as cellSize asks for, but no more cells than
    // the tile has agents (a sparse crowd over a large map would otherwise
    // hold more cells than agents).
    const uint32_t wanted = std::max(1u, uint32_t(mTileSize / cellSize));
    uint32_t cells = 0;
    for (uint32_t t : tiles.occupied) {
        const uint32_t count = tiles.start[t + 1] - tiles.start[t];
        const uint32_t side = std::min(wanted, std::max(1u, uint32_t(std::sqrt(float(count)))));
        mTiles[t] = {cells, side, float(side) / mTileSize};
        cells += side * side + 1;
    }
    mCellStart.resize(cells);
    mAgent.resize(positions.size());
    mPosition.resize(positions.size());
    // Each tile on its own: a counting sort of its agents by cell into the
    // slots the bins gave the tile, in the bins' order within a cell.
    core::parallelForRanges(uint32_t(tiles.occupied.size()), 8, threads, [&](core::IndexRange range) {
        for (uint32_t k = range.begin; k < range.end; ++k) {
            const uint32_t t = tiles.occupied[k];
            const TileCells& tile = mTiles[t];
            const glm::vec2 origin = glm::vec2(float(t % mTilesX), float(t / mTilesX)) * mTileSize;
            const int32_t last = int32_t(tile.side) - 1;
            auto cellOf = [&](uint32_t a) {
                const int32_t cx = std::clamp(floorToInt((positions[a].x - origin.x) * tile.inverseCell), 0, last);
                const int32_t cz = std::clamp(floorToInt((positions[a].z - origin.y) * tile.inverseCell), 0, last);
                return uint32_t(cz) * tile.side + uint32_t(cx);
            };
            const std::span<const uint32_t> agents = tiles.order.subspan(tiles.start[t], tiles.start[t + 1] - tiles.start[t]);
            // Counted one place up, so that after the prefix sum start[c + 1]
            // is cell c's first slot, and after the scatter (which advances
            // it) its end: cell c + 1's first slot.
            uint32_t* start = mCellStart.data() + tile.first;
            std::fill(start, start + tile.side * tile.side + 1, 0u);
            for (uint32_t a : agents) ++start[cellOf(a) + 1];
            uint32_t slot = tiles.start[t];
            start[0] = slot;
            for (uint32_t c = 1; c <= tile.side * tile.side; ++c) slot += std::exchange(start[c], slot);
            for (uint32_t a : agents) {
                const uint32_t s = start[cellOf(a) + 1]++;
                mAgent[s] = a;
                mPosition[s] = {positions[a].x, positions[a].z};
            }
        }
    });
}

uint32_t NeighbourGrid::nearest(glm::vec2 p, uint32_t self, float closeRadius, float radius, uint32_t count,
                                NearAgent* out) const {
    // Kept sorted by distance, then by agent index.
    float distance[kMaxNearest];
    uint32_t slotOf[kMaxNearest], agentOf[kMaxNearest];
    uint32_t found = 0;
    auto after = [&](uint32_t k, float d, uint32_t agent) {
        return distance[k] > d || (distance[k] == d && agentOf[k] > agent);
    };
    auto look = [&](float reach, float lo2, float hi2) {
        forEachRun(p, reach, [&](uint32_t first, uint32_t end) {
            // Two passes per batch of slots: the tests without branches
            // (which way each goes is a coin toss), then the few that passed.
            constexpr uint32_t kBatch = 32;
            uint32_t batch[kBatch];
            float batchDistance[kBatch];
            for (uint32_t begin = first; begin < end; begin += kBatch) {
                const uint32_t stop = std::min(end, begin + kBatch);
                uint32_t passed = 0;
                for (uint32_t s = begin; s < stop; ++s) {
                    const glm::vec2 offset = mPosition[s] - p;
                    const float d = offset.x * offset.x + offset.y * offset.y;
                    batch[passed] = s;
                    batchDistance[passed] = d;
                    passed += (d > lo2) & (d <= hi2) & (mAgent[s] != self);
                }
                for (uint32_t k = 0; k < passed; ++k) {
                    const float d = batchDistance[k];
                    const uint32_t agent = mAgent[batch[k]];
                    if (found == count && !after(count - 1, d, agent)) continue;
                    uint32_t at = found < count ? found++ : count - 1;
                    for (; at > 0 && after(at - 1, d, agent); --at) {
                        distance[at] = distance[at - 1];
                        slotOf[at] = slotOf[at - 1];
                        agentOf[at] = agentOf[at - 1];
                    }
                    distance[at] = d;
                    slotOf[at] = batch[k];
                    agentOf[at] = agent;
                }
            }
        });
    };
    const float close2 = closeRadius * closeRadius, radius2 = radius * radius;
    if (closeRadius < radius) {
        look(closeRadius, -1.0f, close2);
        if (found < count) look(radius, close2, radius2);
    } else {
        look(radius, -1.0f, radius2);
    }
    for (uint32_t k = 0; k < found; ++k) out[k] = {agentOf[k], distance[k], mPosition[slotOf[k]] - p};
    return found;
}

size_t NeighbourGrid::bytes() const {
    return mTiles.capacity() * sizeof(TileCells) + (mCellStart.capacity() + mAgent.capacity()) * sizeof(uint32_t) +
           mPosition.capacity() * sizeof(glm::vec2);
}

} // namespace tessera::crowd
