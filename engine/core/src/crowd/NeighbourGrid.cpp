#include "NeighbourGrid.h"

#include "tessera/core/ParallelFor.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace tessera::crowd {

void NeighbourGrid::build(std::span<const glm::vec3> positions, const TileAgents& tiles, float cellSize,
                          uint32_t threads) {
    mInverseCell = 1.0f / tiles.cellSize;
    constexpr uint32_t n = NavGrid::kTileCells;
    mTileSize = float(n) * tiles.cellSize;
    mWidth = tiles.width;
    mHeight = tiles.height;
    mTilesX = (mWidth + n - 1) / n;
    mTilesZ = (mHeight + n - 1) / n;
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
    // The agent itself is among the slots, at distance 0 (its position is
    // stored as it is): the count + 1 nearest are kept, and it is dropped
    // at the end, rather than tested for at every slot.
    const uint32_t keepCount = count + 1;
    // Kept sorted by distance, then by agent index.
    float distance[kMaxNearest + 1];
    uint32_t slotOf[kMaxNearest + 1], agentOf[kMaxNearest + 1];
    uint32_t found = 0;
    // Slots within reach, gathered without branches (whether a slot is in
    // reach is a coin toss, and mispredicted branches were most of a query's
    // time), then kept or not a few at a time.
    constexpr uint32_t kBatch = 64;
    uint32_t batch[kBatch];
    float batchDistance[kBatch];
    uint32_t gathered = 0;
    auto keep = [&] {
        for (uint32_t k = 0; k < gathered; ++k) {
            const float d = batchDistance[k];
            const uint32_t agent = mAgent[batch[k]];
            auto after = [&](uint32_t at) { return distance[at] > d || (distance[at] == d && agentOf[at] > agent); };
            if (found == keepCount && !after(keepCount - 1)) continue;
            uint32_t at = found < keepCount ? found++ : keepCount - 1;
            for (; at > 0 && after(at - 1); --at) {
                distance[at] = distance[at - 1];
                slotOf[at] = slotOf[at - 1];
                agentOf[at] = agentOf[at - 1];
            }
            distance[at] = d;
            slotOf[at] = batch[k];
            agentOf[at] = agent;
        }
        gathered = 0;
    };
    // Within reach: d <= hi2, and beyond lo2 when looking past a first look.
    auto look = [&]<bool kRing>(float reach, float lo2, float hi2) {
        forEachRun(p, reach, [&](uint32_t first, uint32_t end) {
            for (uint32_t begin = first; begin < end; begin += kBatch) {
                const uint32_t stop = std::min(end, begin + kBatch);
                if (gathered + (stop - begin) > kBatch) keep();
                for (uint32_t s = begin; s < stop; ++s) {
                    const glm::vec2 offset = mPosition[s] - p;
                    const float d = offset.x * offset.x + offset.y * offset.y;
                    batch[gathered] = s;
                    batchDistance[gathered] = d;
                    gathered += kRing ? (d > lo2) & (d <= hi2) : d <= hi2;
                }
            }
        });
        keep();
    };
    const float close2 = closeRadius * closeRadius, radius2 = radius * radius;
    if (closeRadius < radius) {
        look.template operator()<false>(closeRadius, 0.0f, close2);
        // The agent itself was found in the first look.
        if (found < keepCount) look.template operator()<true>(radius, close2, radius2);
    } else {
        look.template operator()<false>(radius, 0.0f, radius2);
    }
    uint32_t kept = 0;
    for (uint32_t k = 0; k < found && kept < count; ++k)
        if (agentOf[k] != self) out[kept++] = {agentOf[k], distance[k], mPosition[slotOf[k]] - p};
    return kept;
}

size_t NeighbourGrid::agentBytes() const {
    return (mCellStart.capacity() + mAgent.capacity()) * sizeof(uint32_t) + mPosition.capacity() * sizeof(glm::vec2);
}

size_t NeighbourGrid::tileBytes() const { return mTiles.capacity() * sizeof(TileCells); }

} // namespace tessera::crowd
