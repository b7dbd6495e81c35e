#include "tessera/subdiv/PtexTopology.h"

#include <algorithm>
#include <string>
#include <unordered_map>

namespace tessera::subdiv {

namespace {

// A tile edge that lies on a base edge: the part [lo, hi] (in halves) of the
// directed base edge it walks, its t = 0 at lo. Quad edges take the whole
// edge; sub-face k's edge 0 is the first half of (v_k, v_k+1) and its edge 3
// the second half of (v_k-1, v_k).
struct EdgePart {
    uint32_t face = 0;
    uint32_t tile = 0;
    uint8_t edge = 0;
    uint8_t lo = 0, hi = 2;
};

uint64_t directedKey(uint32_t from, uint32_t to) {
    return (uint64_t(from) << 32) | uint64_t(to);
}

// Position x (halves along the part's directed base edge) as the part's own
// edge parameter, in halves.
uint8_t partT(const EdgePart& part, int x) {
    return uint8_t((x - part.lo) * 2 / (part.hi - part.lo));
}

void addLink(PtexTile& tile, uint32_t edge, const TileLink& link) {
    TileEdge& e = tile.edges[edge];
    e.links[e.count++] = link;
    if (e.count == 2 && e.links[0].lo > e.links[1].lo) std::swap(e.links[0], e.links[1]);
}

} // namespace

Result<PtexTopology> PtexTopology::create(const ObjShape& shape) {
    if (shape.faceSizes.empty()) return fail(shape.name, ": no faces");
    PtexTopology topology;
    std::vector<bool> hole(shape.faceCount(), false);
    for (uint32_t face : shape.holes)
        if (face < shape.faceCount()) hole[face] = true;
    size_t offset = 0;
    for (uint32_t f = 0; f < shape.faceCount(); ++f) {
        const uint32_t n = shape.faceSizes[f];
        if (n < 3 || n > kMaxFaceVertices)
            return fail(shape.name, ": face ", std::to_string(f), " has ", std::to_string(n), " vertices");
        if (offset + n > shape.faceVertices.size()) return fail(shape.name, ": face vertex list too short");
        for (uint32_t i = 0; i < n; ++i)
            if (shape.faceVertices[offset + i] >= shape.positions.size())
                return fail(shape.name, ": face ", std::to_string(f), " names a missing vertex");
        offset += n;
        topology.mFirstTile.push_back(topology.tileCount());
        for (uint32_t k = 0; k < (n == 4 ? 1u : n); ++k)
            topology.mTiles.push_back({.baseFace = f, .subFace = k, .isSubFace = n != 4, .hole = hole[f]});
    }
    topology.mFirstTile.push_back(topology.tileCount());
    if (Status linked = topology.linkEdges(shape); !linked) return linked.error();
    topology.buildFans();
    return topology;
}

Status PtexTopology::linkEdges(const ObjShape& shape) {
    // Tiles of holes stay unlinked: no surface reaches across a hole's edge.
    std::unordered_map<uint64_t, std::vector<EdgePart>> parts;
    size_t offset = 0;
    for (uint32_t f = 0; f < shape.faceCount(); ++f) {
        const uint32_t n = shape.faceSizes[f];
        const uint32_t* v = shape.faceVertices.data() + offset;
        offset += n;
        const uint32_t first = mFirstTile[f];
        if (mTiles[first].hole) continue;
        if (n == 4) {
            for (uint8_t e = 0; e < 4; ++e) parts[directedKey(v[e], v[(e + 1) % 4])].push_back({f, first, e, 0, 2});
            continue;
        }
        for (uint32_t k = 0; k < n; ++k) {
            const uint32_t next = (k + 1) % n, prev = (k + n - 1) % n;
            parts[directedKey(v[k], v[next])].push_back({f, first + k, 0, 0, 1});
            parts[directedKey(v[prev], v[k])].push_back({f, first + k, 3, 1, 2});
            // Inner edges: sub-face k's edge 1 (edge midpoint to centre) is
            // sub-face k+1's edge 2 (centre to the same midpoint).
            addLink(mTiles[first + k], 1, {.tile = first + next, .edge = 2});
            addLink(mTiles[first + next], 2, {.tile = first + k, .edge = 1});
        }
    }
    // One face per direction: a second one means an edge of three faces or
    // two faces wound the same way, which OpenSubdiv refuses too.
    for (const auto& [key, mine] : parts) {
        // A named copy of the binding: lambdas capture structured bindings
        // only from C++20 compilers newer than Debian's clang 14.
        const uint32_t firstFace = mine[0].face;
        if (std::any_of(mine.begin(), mine.end(), [firstFace](const EdgePart& p) { return p.face != firstFace; }))
            return fail(shape.name, ": the edge between vertices ", std::to_string(key >> 32), " and ",
                        std::to_string(uint32_t(key)),
                        " is walked the same way by two faces (non-manifold or inconsistent winding)");
    }
    for (const auto& [key, mine] : parts) {
        const uint32_t from = uint32_t(key >> 32), to = uint32_t(key);
        const auto opposite = parts.find(directedKey(to, from));
        if (opposite == parts.end()) continue; // a boundary edge
        for (const EdgePart& p : mine)
            for (const EdgePart& q : opposite->second) {
                // q's part in p's direction is [2 - q.hi, 2 - q.lo].
                const int lo = std::max<int>(p.lo, 2 - q.hi), hi = std::min<int>(p.hi, 2 - q.lo);
                if (hi <= lo) continue;
                addLink(mTiles[p.tile], p.edge,
                        {.tile = q.tile,
                         .edge = q.edge,
                         .lo = partT(p, lo),
                         .hi = partT(p, hi),
                         .theirLo = partT(q, 2 - lo),
                         .theirHi = partT(q, 2 - hi)});
            }
    }
    return {};
}

std::span<const TileCorner> PtexTopology::fanCorners(uint32_t fan) const {
    const Fan& f = mFans[fan];
    return std::span<const TileCorner>(mFanCorners).subspan(f.firstCorner, f.cornerCount);
}

std::optional<TilePoint> PtexTopology::acrossEdge(uint32_t tile, uint32_t edge, glm::dvec2 uv) const {
    const TileEdge& e = mTiles[tile].edges[edge];
    if (e.count == 0) return std::nullopt;
    const glm::dvec2 td = edgeCoords(edge, uv);
    // Two links split the edge at t = 0.5; a point past either end belongs
    // to the link at that end.
    const TileLink& link = e.count == 2 && td.x >= 0.5 ? e.links[1] : e.links[0];
    return TilePoint{link.tile, edgePoint(link.edge, link.theirT(td.x), -td.y * link.scale())};
}

std::optional<TilePoint> PtexTopology::resolve(uint32_t tile, glm::dvec2 uv) const {
    TilePoint point{tile, uv};
    for (int crossing = 0; crossing <= 2; ++crossing) {
        const glm::dvec2 p = point.uv;
        const bool outside[4] = {p.y<0.0, p.x> 1.0, p.y > 1.0, p.x < 0.0};
        if (!outside[0] && !outside[1] && !outside[2] && !outside[3]) return point;
        if (crossing == 2) break;
        std::optional<TilePoint> next;
        for (uint32_t e = 0; e < 4 && !next; ++e)
            if (outside[e]) next = acrossEdge(point.tile, e, p);
        if (!next) return std::nullopt;
        point = *next;
    }
    return std::nullopt;
}

glm::dvec2 PtexTopology::edgePoint(uint32_t edge, double t, double depth) {
    switch (edge & 3u) {
    case 0:
        return {t, depth};
    case 1:
        return {1.0 - depth, t};
    case 2:
        return {1.0 - t, 1.0 - depth};
    default:
        return {depth, 1.0 - t};
    }
}

glm::dvec2 PtexTopology::edgeCoords(uint32_t edge, glm::dvec2 uv) {
    switch (edge & 3u) {
    case 0:
        return {uv.x, uv.y};
    case 1:
        return {uv.y, 1.0 - uv.x};
    case 2:
        return {1.0 - uv.x, 1.0 - uv.y};
    default:
        return {1.0 - uv.y, uv.x};
    }
}

glm::dvec2 PtexTopology::cornerUV(uint32_t corner) {
    static constexpr double kCorner[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    return {kCorner[corner & 3u][0], kCorner[corner & 3u][1]};
}

} // namespace tessera::subdiv
