// PtexTopology's fans: the tile corners around each ptex vertex, found by
// walking from corner to corner across the tiles' links.
#include "tessera/subdiv/PtexTopology.h"

#include <algorithm>

namespace tessera::subdiv {

namespace {

enum class WalkEnd { Closed, Boundary, TJunction };

struct Walk {
    std::vector<TileCorner> corners; // not counting the start
    WalkEnd end = WalkEnd::Boundary;
};

bool same(const TileCorner& a, const TileCorner& b) {
    return a.tile == b.tile && a.corner == b.corner;
}

// Corner c starts edge c: across it at t = 0 lies the neighbour's t =
// theirLo / 2, its corner edge + 1 if that is 1, the middle of its edge (a
// T-junction) if 0.5. Going on from that corner crosses its own edge + 1.
Walk walkForward(std::span<const PtexTile> tiles, TileCorner start) {
    Walk walk;
    TileCorner at = start;
    for (size_t step = 0; step <= 4 * tiles.size(); ++step) {
        const TileEdge& edge = tiles[at.tile].edges[at.corner];
        if (edge.count == 0 || edge.links[0].lo != 0) return walk;
        const TileLink& link = edge.links[0];
        if (link.theirLo != 2) {
            walk.end = WalkEnd::TJunction;
            return walk;
        }
        const TileCorner next{link.tile, uint8_t((link.edge + 1) % 4)};
        if (same(next, start)) {
            walk.end = WalkEnd::Closed;
            return walk;
        }
        walk.corners.push_back(next);
        at = next;
    }
    return walk; // unreachable on a consistent topology
}

// The other way: corner c ends edge c - 1, reached at t = 1 (theirHi).
Walk walkBackward(std::span<const PtexTile> tiles, TileCorner start) {
    Walk walk;
    TileCorner at = start;
    for (size_t step = 0; step <= 4 * tiles.size(); ++step) {
        const TileEdge& edge = tiles[at.tile].edges[(at.corner + 3) % 4];
        if (edge.count == 0 || edge.links[edge.count - 1].hi != 2) return walk;
        const TileLink& link = edge.links[edge.count - 1];
        if (link.theirHi != 0) {
            walk.end = WalkEnd::TJunction;
            return walk;
        }
        const TileCorner next{link.tile, link.edge};
        walk.corners.push_back(next);
        at = next;
    }
    return walk;
}

FanKind kindOf(WalkEnd forward, WalkEnd backward, size_t count) {
    if (forward == WalkEnd::Closed) return count == 4 ? FanKind::Regular : FanKind::Extraordinary;
    if (forward == WalkEnd::TJunction && backward == WalkEnd::TJunction && count == 2) return FanKind::TJunction;
    if (forward == WalkEnd::Boundary && backward == WalkEnd::Boundary) {
        if (count == 1) return FanKind::Corner;
        if (count == 2) return FanKind::Boundary;
    }
    return FanKind::Extraordinary;
}

} // namespace

void PtexTopology::buildFans() {
    constexpr uint32_t kUnset = 0xffffffffu;
    for (PtexTile& tile : mTiles) tile.fans.fill(kUnset);
    for (uint32_t t = 0; t < tileCount(); ++t)
        for (uint8_t c = 0; c < 4; ++c) {
            if (mTiles[t].fans[c] != kUnset) continue;
            const TileCorner start{t, c};
            const Walk forward = walkForward(mTiles, start);
            Walk backward;
            if (forward.end != WalkEnd::Closed) backward = walkBackward(mTiles, start);
            // Around the point in order: the backward walk reversed, the
            // start, then the forward walk.
            Fan fan;
            fan.firstCorner = uint32_t(mFanCorners.size());
            mFanCorners.insert(mFanCorners.end(), backward.corners.rbegin(), backward.corners.rend());
            mFanCorners.push_back(start);
            mFanCorners.insert(mFanCorners.end(), forward.corners.begin(), forward.corners.end());
            fan.cornerCount = uint32_t(mFanCorners.size()) - fan.firstCorner;
            fan.kind = kindOf(forward.end, backward.end, fan.cornerCount);
            const uint32_t id = fanCount();
            mFans.push_back(fan);
            for (const TileCorner& corner : fanCorners(id)) mTiles[corner.tile].fans[corner.corner] = id;
        }
}

} // namespace tessera::subdiv
