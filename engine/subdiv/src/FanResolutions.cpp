#include "FanResolutions.h"

#include <algorithm>
#include <string>

namespace tessera::subdiv::detail {

namespace {

// A quad's edge with two links (a T-junction): its end fans and the fan at
// the midpoint, where the first half's sub-face has a corner.
struct TEdge {
    uint32_t start = 0, end = 0, middle = 0;
};

std::vector<TEdge> tJunctionEdges(const PtexTopology& topology) {
    std::vector<TEdge> edges;
    for (const PtexTile& tile : topology.tiles())
        for (uint32_t e = 0; e < 4; ++e) {
            if (tile.edges[e].count != 2) continue;
            const TileLink& first = tile.edges[e].links[0];
            // The neighbour's t at this edge's midpoint (the link's hi):
            // 0 is the start of its edge (corner edge), 1 its end.
            const uint32_t corner = first.theirHi == 0 ? first.edge : (first.edge + 1u) % 4u;
            edges.push_back({tile.fans[e], tile.fans[(e + 1) % 4], topology.tile(first.tile).fans[corner]});
        }
    return edges;
}

} // namespace

Result<std::vector<uint8_t>> fanResolutions(const PtexTopology& topology, std::span<const uint8_t> log2Size) {
    std::vector<uint8_t> resolution(topology.fanCount(), 0xff);
    for (uint32_t f = 0; f < topology.fanCount(); ++f)
        for (const TileCorner& corner : topology.fanCorners(f)) {
            const uint32_t own = log2Size[corner.tile] + (topology.tile(corner.tile).isSubFace ? 1u : 0u);
            resolution[f] = uint8_t(std::min<uint32_t>(resolution[f], own));
        }
    const std::vector<TEdge> tEdges = tJunctionEdges(topology);
    for (bool changed = true; changed;) {
        changed = false;
        for (const TEdge& t : tEdges) {
            const uint8_t low = std::min({resolution[t.start], resolution[t.end], resolution[t.middle]});
            for (uint32_t f : {t.start, t.end, t.middle})
                if (resolution[f] != low) resolution[f] = low, changed = true;
        }
    }
    for (uint32_t t = 0; t < topology.tileCount(); ++t) {
        const PtexTile& tile = topology.tile(t);
        const uint32_t coarsest = tile.isSubFace ? 2u : 1u;
        for (uint32_t c = 0; c < 4; ++c)
            if (resolution[tile.fans[c]] < coarsest)
                return fail("displacement tiles: tile ", std::to_string(t),
                            " (a sub-face) shares a vertex with a quad tile of log2 size 1; quad tiles next to "
                            "non-quad faces need 2 or more");
    }
    return resolution;
}

} // namespace tessera::subdiv::detail
