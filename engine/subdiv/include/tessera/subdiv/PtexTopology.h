#pragma once
/// @file PtexTopology.h
/// The ptex faces of a control mesh as tiles of a displacement texture, and
/// how they meet: the adjacency the tile format's overlaps, corner averages
/// and level limits are computed from (docs/SUBDIV.md, "Tiles").
///
/// A quad base face is one tile; an n-gon (n != 4) is n tiles, its
/// sub-faces, numbered as OpenSubdiv numbers ptex faces (SubdivSurface::
/// firstPtexFace). A tile's (u, v) in [0, 1]^2 is its ptex face's: for a
/// quad (0, 0) at face vertex 0, u towards vertex 1, v towards vertex 3; for
/// sub-face k of an n-gon (0, 0) at vertex k, u towards the midpoint of edge
/// (k, k+1), v towards the midpoint of edge (k-1, k), (1, 1) at the centre
/// (FaceParameterization). OpenSubdiv 3.5 keeps every patch in this
/// orientation (its PatchParam has no rotation), so the tile's (u, v) is
/// what a patch's PatchParam offset and depth address.
///
/// Tile corners are numbered 0: (0, 0), 1: (1, 0), 2: (1, 1), 3: (0, 1);
/// edge e runs from corner e to corner e+1 (0: v = 0, 1: u = 1, 2: v = 1,
/// 3: u = 0, PatchParam's mask order), with parameter t in [0, 1] from its
/// first corner. A sub-face edge on a base edge is half of that edge, so a
/// quad next to an n-gon meets two sub-faces along one edge (a
/// T-junction): the quad's edge has two links, each sub-face's one link
/// to half of the quad's edge.
///
/// Tiles meeting at a point form a fan (a ptex vertex): the tile corners
/// around it, in order. Hole faces get tiles (ptex numbering counts them)
/// but are linked to nothing.

#include "tessera/core/Result.h"
#include "tessera/subdiv/ObjShape.h"

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace tessera::subdiv {

inline constexpr uint32_t kNoTile = 0xffffffffu;

/// What lies across a part of a tile edge. Edge parameters are stored in
/// halves (0, 1, 2 for t = 0, 0.5, 1): a link covers the part [lo, hi] of
/// this edge and maps it onto the neighbour's edge, which runs the other
/// way (theirLo > theirHi).
struct TileLink {
    uint32_t tile = kNoTile; ///< the neighbour; kNoTile: no link
    uint8_t edge = 0;        ///< the neighbour's edge
    uint8_t lo = 0, hi = 2;
    uint8_t theirLo = 2, theirHi = 0; ///< the neighbour's t at lo and at hi

    /// Neighbour units per unit of this tile: 1 between equals, 2 from a
    /// quad into a sub-face, 0.5 from a sub-face into a quad.
    double scale() const { return double(theirLo - theirHi) / double(hi - lo); }
    /// The neighbour's edge parameter at this edge's t (any t: charts
    /// continue past the link's part, which corner texels use).
    double theirT(double t) const { return 0.5 * theirLo - (t - 0.5 * lo) * scale(); }
};

/// One tile edge: no link (a boundary), one, or two (a quad's edge along an
/// n-gon: the halves [0, 1] and [1, 2]).
struct TileEdge {
    std::array<TileLink, 2> links{};
    uint8_t count = 0;
};

/// How the tiles meet at a fan's point; what a corner texel takes there.
enum class FanKind : uint8_t {
    Regular,       ///< four tiles around an interior point: the diagonal tile's texel
    TJunction,     ///< two sub-faces at the midpoint of a quad's edge: the quad's texel
    Extraordinary, ///< any other closed fan, or an open one of three tiles or more: averaged 2x2 blocks
    Boundary,      ///< two tiles at a boundary point: extrapolated across the boundary
    Corner,        ///< one tile (a mesh corner, or any corner of a hole tile): extrapolated
};

struct TileCorner {
    uint32_t tile = 0;
    uint8_t corner = 0;
};

/// A ptex vertex: its corners, in order around it.
struct Fan {
    FanKind kind = FanKind::Corner;
    uint32_t firstCorner = 0; ///< into PtexTopology::fanCorners()
    uint32_t cornerCount = 0;
};

struct PtexTile {
    uint32_t baseFace = 0;
    uint32_t subFace = 0;   ///< k for sub-face k of an n-gon, 0 for a quad
    bool isSubFace = false; ///< half the scale of a quad along base edges
    bool hole = false;
    std::array<uint32_t, 4> fans{}; ///< the fan of each corner
    std::array<TileEdge, 4> edges{};
};

/// A point in a tile's chart (coordinates may lie outside [0, 1]^2).
struct TilePoint {
    uint32_t tile = 0;
    glm::dvec2 uv{0.0};
};

class PtexTopology {
public:
    /// The tiles of `shape`. Errors: a face size outside 3..kMaxFaceVertices,
    /// a vertex index out of range, an edge walked twice the same way or by
    /// more than two faces (non-manifold or inconsistently wound).
    static Result<PtexTopology> create(const ObjShape& shape);

    uint32_t tileCount() const { return uint32_t(mTiles.size()); }
    const PtexTile& tile(uint32_t tile) const { return mTiles[tile]; }
    std::span<const PtexTile> tiles() const { return mTiles; }
    uint32_t baseFaceCount() const { return uint32_t(mFirstTile.size() - 1); }
    /// The tile of base face `face`'s sub-face 0 (SubdivSurface::firstPtexFace).
    uint32_t firstTile(uint32_t face) const { return mFirstTile[face]; }

    uint32_t fanCount() const { return uint32_t(mFans.size()); }
    const Fan& fan(uint32_t fan) const { return mFans[fan]; }
    std::span<const TileCorner> fanCorners(uint32_t fan) const;
    std::span<const Fan> fans() const { return mFans; }

    /// The point `uv` of `tile`'s chart, continued across `edge` into the
    /// neighbour's chart (the link covering the point's t, or the nearest
    /// one for a t past the edge's ends); nothing across a boundary.
    std::optional<TilePoint> acrossEdge(uint32_t tile, uint32_t edge, glm::dvec2 uv) const;
    /// The tile whose [0, 1]^2 holds `uv` of `tile`'s chart, within two
    /// crossings (a corner texel's point at a regular vertex or a
    /// T-junction); nothing if no chain of links reaches it.
    std::optional<TilePoint> resolve(uint32_t tile, glm::dvec2 uv) const;

    /// Tile (u, v) of the point at parameter t along `edge`, `depth` into
    /// the tile (negative: outside).
    static glm::dvec2 edgePoint(uint32_t edge, double t, double depth);
    /// The inverse: (t, depth) of `uv` relative to `edge`.
    static glm::dvec2 edgeCoords(uint32_t edge, glm::dvec2 uv);
    static glm::dvec2 cornerUV(uint32_t corner);

private:
    Status linkEdges(const ObjShape& shape);
    void buildFans();

    std::vector<PtexTile> mTiles;
    std::vector<uint32_t> mFirstTile; ///< per base face, and the tile count last
    std::vector<Fan> mFans;
    std::vector<TileCorner> mFanCorners;
};

} // namespace tessera::subdiv
