#include "TileDeriver.h"

#include "tessera/shaders/DisplacementTile.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace tessera::subdiv::detail {

namespace {

// The interior texel at corner c of an n x n level (1-based).
glm::uvec2 cornerTexel(uint32_t corner, uint32_t n) {
    return {corner == 1 || corner == 2 ? n : 1u, corner >= 2 ? n : 1u};
}

} // namespace

TileDeriver::TileDeriver(const TileStorage& storage) : mStorage(storage) {
    for (uint32_t t = 0; t < storage.topology->tileCount(); ++t)
        mMaxResolution = std::max(mMaxResolution, resolutionOf(t, 0));
}

uint32_t TileDeriver::resolutionOf(uint32_t tile, uint32_t level) const {
    return mStorage.log2Size[tile] - level + (mStorage.topology->tile(tile).isSubFace ? 1u : 0u);
}

int TileDeriver::levelAt(uint32_t tile, uint32_t resolution) const {
    const int level = int(resolutionOf(tile, 0)) - int(resolution);
    return level >= 0 && level < int(mStorage.log2Size[tile]) ? level : -1;
}

float& TileDeriver::at(uint32_t tile, uint32_t level, uint32_t x, uint32_t y) {
    assert(x <= sizeOf(tile, level) + 1 && y <= sizeOf(tile, level) + 1);
    const glm::uvec2 p = mStorage.origins[tile] + shader::tsTileMipOffset(mStorage.log2Size[tile], level);
    return mStorage.texels[size_t(p.y + y) * mStorage.width + p.x + x];
}

float TileDeriver::at(uint32_t tile, uint32_t level, uint32_t x, uint32_t y) const {
    return const_cast<TileDeriver*>(this)->at(tile, level, x, y);
}

float TileDeriver::underived(uint32_t tile, uint32_t level, uint32_t x, uint32_t y) const {
    if (level == 0) {
        const uint32_t n = sizeOf(tile, 0);
        return mStorage.coefficients[mStorage.firstCoefficient[tile] + size_t(y - 1) * n + (x - 1)];
    }
    // Haar: the mean of the 2x2 texels above (1-based 2x-1 .. 2x).
    const uint32_t above = level - 1;
    return 0.25f * ((at(tile, above, 2 * x - 1, 2 * y - 1) + at(tile, above, 2 * x, 2 * y - 1)) +
                    (at(tile, above, 2 * x - 1, 2 * y) + at(tile, above, 2 * x, 2 * y)));
}

void TileDeriver::deriveInteriors(std::span<const uint32_t> tiles, std::span<const uint32_t> fans) {
    for (uint32_t resolution = mMaxResolution; resolution >= 1; --resolution) {
        for (uint32_t tile : tiles) {
            const int level = levelAt(tile, resolution);
            if (level < 0) continue;
            const uint32_t n = sizeOf(tile, uint32_t(level));
            for (uint32_t y = 1; y <= n; ++y)
                for (uint32_t x = 1; x <= n; ++x) at(tile, level, x, y) = underived(tile, level, x, y);
        }
        for (uint32_t fan : fans) averageFan(fan, resolution);
    }
}

void TileDeriver::averageFan(uint32_t fan, uint32_t resolution) {
    // Section 4.2: every tile's 2x2 corner block at an extraordinary vertex
    // takes one value, the mean of their corner coefficients, so D is equal
    // there from every side and its derivatives vanish. Only the interior
    // corner texel is written here; the overlaps copy it.
    const PtexTopology& topology = *mStorage.topology;
    assert(topology.fan(fan).kind == FanKind::Extraordinary);
    double sum = 0.0;
    uint32_t count = 0;
    for (const TileCorner& c : topology.fanCorners(fan)) {
        const int level = levelAt(c.tile, resolution);
        if (level < 0) continue;
        const glm::uvec2 p = cornerTexel(c.corner, sizeOf(c.tile, uint32_t(level)));
        sum += underived(c.tile, uint32_t(level), p.x, p.y);
        ++count;
    }
    if (count == 0) return;
    const float mean = float(sum / count);
    for (const TileCorner& c : topology.fanCorners(fan)) {
        const int level = levelAt(c.tile, resolution);
        if (level < 0) continue;
        const glm::uvec2 p = cornerTexel(c.corner, sizeOf(c.tile, uint32_t(level)));
        at(c.tile, uint32_t(level), p.x, p.y) = mean;
    }
}

void TileDeriver::deriveOverlaps(std::span<const uint32_t> tiles) {
    mRefined.clear();
    for (uint32_t tile : tiles)
        for (uint32_t level = 0; level < mStorage.log2Size[tile]; ++level) {
            const uint32_t n = sizeOf(tile, level);
            for (uint32_t y = 0; y <= n + 1; ++y)
                for (uint32_t x = 0; x <= n + 1; x += (y == 0 || y == n + 1) ? 1 : n + 1)
                    at(tile, level, x, y) = overlapValue(tile, level, x, y);
        }
    mRefined.clear();
}

float TileDeriver::texelValue(uint32_t tile, uint32_t level, uint32_t x, uint32_t y) {
    const uint32_t n = sizeOf(tile, level);
    if (x >= 1 && x <= n && y >= 1 && y <= n) return at(tile, level, x, y);
    return overlapValue(tile, level, x, y);
}

float TileDeriver::texelAtPoint(uint32_t tile, uint32_t level, glm::dvec2 uv) {
    // Texel x is centred at (x - 0.5) / n; points here are such centres,
    // dyadic, so the products are exact.
    const double n = sizeOf(tile, level);
    const double x = uv.x * n + 0.5, y = uv.y * n + 0.5;
    assert(x == std::floor(x) && y == std::floor(y) && x >= 0.0 && y >= 0.0);
    return texelValue(tile, level, uint32_t(x), uint32_t(y));
}

float TileDeriver::virtualTexel(uint32_t tile, uint32_t resolution, glm::dvec2 uv) {
    const int level = levelAt(tile, resolution);
    if (level >= 0) return texelAtPoint(tile, uint32_t(level), uv);
    const uint32_t finest = resolutionOf(tile, 0), coarsest = resolutionOf(tile, mStorage.log2Size[tile] - 1);
    if (resolution < coarsest) {
        // Only a quad's coarsest level (1) meets a sub-face's (2): one Haar
        // step below the 2x2 level, a single interior texel.
        assert(resolution + 1 == coarsest);
        return underived(tile, mStorage.log2Size[tile], 1, 1);
    }
    const double n = double(1u << (resolution - finest + mStorage.log2Size[tile]));
    const double x = uv.x * n + 0.5, y = uv.y * n + 0.5;
    assert(x == std::floor(x) && y == std::floor(y) && x >= 0.0 && y >= 0.0);
    return refined(tile, resolution, uint32_t(x), uint32_t(y));
}

float TileDeriver::refined(uint32_t tile, uint32_t resolution, uint32_t x, uint32_t y) {
    if (resolution == resolutionOf(tile, 0)) return texelValue(tile, 0, x, y);
    const uint64_t key = (uint64_t(tile) << 40) ^ (uint64_t(resolution) << 36) ^ (uint64_t(x) << 18) ^ y;
    if (const auto hit = mRefined.find(key); hit != mRefined.end()) return hit->second;
    // Texel x (centre (x - 0.5) / 2n) of the finer grid lies a quarter of a
    // coarse texel from coarse texel (x + 1) / 2 and three quarters from
    // the next one out: weights 3/4 and 1/4 per axis. The two off-diagonal
    // terms are added first, so the value does not depend on which axis is
    // which (two tiles refine one corner in different orientations).
    const uint32_t px = (x + 1) / 2, qx = x % 2 ? px - 1 : px + 1;
    const uint32_t py = (y + 1) / 2, qy = y % 2 ? py - 1 : py + 1;
    const uint32_t up = resolution - 1;
    const float near = refined(tile, up, px, py), far = refined(tile, up, qx, qy);
    const float sides = refined(tile, up, qx, py) + refined(tile, up, px, qy);
    const float value = (9.0f * near + 3.0f * sides + far) * (1.0f / 16.0f);
    mRefined.emplace(key, value);
    return value;
}

float TileDeriver::extrapolate(uint32_t tile, uint32_t level, uint32_t edge, double t) {
    const double h = 0.5 / sizeOf(tile, level);
    return 2.0f * texelAtPoint(tile, level, PtexTopology::edgePoint(edge, t, h)) -
           texelAtPoint(tile, level, PtexTopology::edgePoint(edge, t, 3.0 * h));
}

float TileDeriver::overlapValue(uint32_t tile, uint32_t level, uint32_t x, uint32_t y) {
    const PtexTopology& topology = *mStorage.topology;
    const PtexTile& info = topology.tile(tile);
    const uint32_t n = sizeOf(tile, level), resolution = resolutionOf(tile, level);
    const double h = 0.5 / n;
    const glm::dvec2 uv = (glm::dvec2(x, y) - 0.5) / double(n);
    const auto extraordinary = [&](uint32_t corner) {
        return topology.fan(info.fans[corner]).kind == FanKind::Extraordinary;
    };
    const auto cornerValue = [&](uint32_t corner) {
        const glm::uvec2 p = cornerTexel(corner, n);
        return at(tile, level, p.x, p.y);
    };
    const bool outsideX = x == 0 || x == n + 1, outsideY = y == 0 || y == n + 1;
    if (!(outsideX && outsideY)) {
        // An edge texel. Next to an extraordinary corner it belongs to the
        // corner's 2x2 block (section 4.2): the averaged corner texel.
        const uint32_t e = outsideY ? (y == 0 ? 0u : 2u) : (x == 0 ? 3u : 1u);
        const double t = PtexTopology::edgeCoords(e, uv).x;
        if (t < 1.0 / n && extraordinary(e)) return cornerValue(e);
        if (t > 1.0 - 1.0 / n && extraordinary((e + 1) % 4)) return cornerValue((e + 1) % 4);
        // The neighbour's texel at this resolution (virtual if it lacks
        // it); across a boundary, extrapolation.
        if (const std::optional<TilePoint> p = topology.acrossEdge(tile, e, uv))
            return virtualTexel(p->tile, resolution, p->uv);
        return extrapolate(tile, level, e, t);
    }
    const uint32_t c = x == 0 ? (y == 0 ? 0u : 3u) : (y == 0 ? 1u : 2u);
    switch (topology.fan(info.fans[c]).kind) {
    case FanKind::Extraordinary:
        return cornerValue(c);
    case FanKind::Regular:
    case FanKind::TJunction:
        // The diagonal tile (regular) or the quad past the midpoint
        // (T-junction).
        if (const std::optional<TilePoint> p = topology.resolve(tile, uv))
            return virtualTexel(p->tile, resolution, p->uv);
        return extrapolate(tile, level, c, -h);
    case FanKind::Boundary:
        // One edge is shared, the other the boundary: extrapolate across
        // the boundary, along the shared edge's overlap texels, as the tile
        // across the shared edge extrapolates its own boundary overlap.
        if (info.edges[c].count != 0) return extrapolate(tile, level, (c + 3) % 4, 1.0 + h);
        return extrapolate(tile, level, c, -h);
    case FanKind::Corner:
        break;
    }
    return extrapolate(tile, level, c, -h);
}

} // namespace tessera::subdiv::detail
