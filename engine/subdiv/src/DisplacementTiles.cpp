#include "tessera/subdiv/DisplacementTiles.h"

#include "FanResolutions.h"
#include "TileAtlas.h"
#include "TileDeriver.h"

#include <algorithm>
#include <cassert>
#include <string>

namespace tessera::subdiv {

namespace {

void sortUnique(std::vector<uint32_t>& v) {
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
}

} // namespace

Result<DisplacementTiles> DisplacementTiles::create(PtexTopology topology, std::vector<uint8_t> log2Sizes) {
    if (log2Sizes.size() != topology.tileCount())
        return fail("displacement tiles: ", std::to_string(log2Sizes.size()), " sizes for ",
                    std::to_string(topology.tileCount()), " tiles");
    for (uint32_t t = 0; t < log2Sizes.size(); ++t)
        if (log2Sizes[t] < TS_TILE_MIN_LOG2_SIZE || log2Sizes[t] > TS_TILE_MAX_LOG2_SIZE)
            return fail("displacement tiles: tile ", std::to_string(t), " has log2 size ", std::to_string(log2Sizes[t]),
                        " (1 .. 12)");
    Result<std::vector<uint8_t>> fans = detail::fanResolutions(topology, log2Sizes);
    if (!fans.ok()) return fans.error();
    std::vector<glm::uvec2> footprints;
    for (uint8_t k : log2Sizes) footprints.push_back(shader::tsTileFootprint(k));
    Result<detail::TileAtlas> atlas = detail::TileAtlas::pack(footprints);
    if (!atlas.ok()) return atlas.error();

    DisplacementTiles tiles;
    tiles.mTopology = std::move(topology);
    tiles.mLog2Size = std::move(log2Sizes);
    tiles.mFanResolution = std::move(fans).value();
    tiles.mOrigins = atlas->origins;
    tiles.mWidth = atlas->width;
    tiles.mHeight = atlas->height;
    tiles.mTexels.assign(size_t(tiles.mWidth) * tiles.mHeight, 0.0f);
    size_t total = 0;
    for (uint8_t k : tiles.mLog2Size) {
        tiles.mFirstCoefficient.push_back(total);
        total += size_t(1) << (2 * k);
    }
    tiles.mFirstCoefficient.push_back(total);
    tiles.mCoefficients.assign(total, 0.0f);
    for (uint32_t t = 0; t < tiles.tileCount(); ++t) {
        const uint32_t k = tiles.mLog2Size[t];
        const PtexTile& tile = tiles.mTopology.tile(t);
        shader::TileRecord record{};
        record.data.x = tiles.mOrigins[t].x | (tiles.mOrigins[t].y << 16);
        record.data.z = (1u << k) | (k << 16);
        for (uint32_t c = 0; c < 4; ++c) {
            const uint32_t fan = tile.fans[c];
            const uint32_t difference = tiles.resolutionOf(t, 0) - tiles.mFanResolution[fan];
            // A quad corner shared with a sub-face: the sub-face has no
            // level matching the quad's 2x2, so neither uses it there.
            const auto corners = tiles.mTopology.fanCorners(fan);
            const bool raise = !tile.isSubFace && std::any_of(corners.begin(), corners.end(), [&](const TileCorner& x) {
                return tiles.mTopology.tile(x.tile).isSubFace;
            });
            record.data.w |= (difference | (raise ? 0x80u : 0u)) << (8 * c);
        }
        tiles.mRecords.push_back(record);
    }
    tiles.rebuild();
    return tiles;
}

std::vector<uint8_t> DisplacementTiles::uniformLog2Sizes(const PtexTopology& topology, uint32_t quadLog2Size) {
    std::vector<uint8_t> sizes;
    for (const PtexTile& tile : topology.tiles())
        sizes.push_back(uint8_t(std::max<int>(int(quadLog2Size) - (tile.isSubFace ? 1 : 0), 1)));
    return legalLog2Sizes(topology, std::move(sizes));
}

std::vector<uint8_t> DisplacementTiles::legalLog2Sizes(const PtexTopology& topology, std::vector<uint8_t> log2Sizes) {
    log2Sizes.resize(topology.tileCount(), 1);
    for (uint8_t& k : log2Sizes) k = std::clamp<uint8_t>(k, TS_TILE_MIN_LOG2_SIZE, TS_TILE_MAX_LOG2_SIZE);
    for (uint32_t f = 0; f < topology.fanCount(); ++f) {
        const auto corners = topology.fanCorners(f);
        if (std::none_of(corners.begin(), corners.end(),
                         [&](const TileCorner& c) { return topology.tile(c.tile).isSubFace; }))
            continue;
        for (const TileCorner& c : corners)
            if (!topology.tile(c.tile).isSubFace) log2Sizes[c.tile] = std::max<uint8_t>(log2Sizes[c.tile], 2);
    }
    return log2Sizes;
}

uint32_t DisplacementTiles::resolutionOf(uint32_t tile, uint32_t level) const {
    return mLog2Size[tile] - level + (mTopology.tile(tile).isSubFace ? 1u : 0u);
}

std::span<const float> DisplacementTiles::coefficients(uint32_t tile) const {
    return std::span<const float>(mCoefficients)
        .subspan(mFirstCoefficient[tile], mFirstCoefficient[tile + 1] - mFirstCoefficient[tile]);
}

float DisplacementTiles::texel(uint32_t tile, uint32_t level, uint32_t x, uint32_t y) const {
    assert(level < levelCount(tile) && x <= (tileSize(tile) >> level) + 1 && y <= (tileSize(tile) >> level) + 1);
    const glm::uvec2 p = mOrigins[tile] + shader::tsTileMipOffset(mLog2Size[tile], level);
    return mTexels[size_t(p.y + y) * mWidth + p.x + x];
}

glm::uvec2 DisplacementTiles::tileOrigin(uint32_t tile) const {
    return mOrigins[tile];
}

std::vector<shader::TileRecord> DisplacementTiles::patchRecords(std::span<const Patch> patches) const {
    std::vector<shader::TileRecord> records;
    records.reserve(patches.size());
    for (const Patch& patch : patches) {
        const PatchParam& param = patch.param;
        shader::TileRecord record = mRecords.at(param.ptexFace());
        const uint32_t level = param.depth() - (param.nonQuadRoot() ? 1u : 0u);
        record.data.y = param.u() | (param.v() << 16);
        record.data.z |= level << 24;
        records.push_back(record);
    }
    return records;
}

TileUpdate DisplacementTiles::setCoefficients(uint32_t tile, glm::uvec2 origin, glm::uvec2 size,
                                              std::span<const float> values) {
    assert(tile < tileCount() && values.size() == size_t(size.x) * size.y);
    [[maybe_unused]] const uint32_t n = tileSize(tile);
    assert(origin.x + size.x <= n && origin.y + size.y <= n);
    std::vector<CoefficientEdit> edits;
    for (uint32_t y = 0; y < size.y; ++y)
        for (uint32_t x = 0; x < size.x; ++x)
            edits.push_back({tile, origin.x + x, origin.y + y, values[size_t(y) * size.x + x]});
    return edit(edits);
}

TileUpdate DisplacementTiles::edit(std::span<const CoefficientEdit> edits) {
    std::vector<uint32_t> edited;
    for (const CoefficientEdit& e : edits) {
        assert(e.tile < tileCount() && e.x < tileSize(e.tile) && e.y < tileSize(e.tile));
        float& c = mCoefficients[mFirstCoefficient[e.tile] + size_t(e.y) * tileSize(e.tile) + e.x];
        if (c == e.value) continue;
        c = e.value;
        edited.push_back(e.tile);
    }
    return rederive(std::move(edited));
}

TileUpdate DisplacementTiles::rederive(std::vector<uint32_t> edited) {
    TileUpdate update;
    sortUnique(edited);
    // Extraordinary fans at the edited tiles' corners: their averages change,
    // and with them the corner texels of every tile around them.
    std::vector<uint32_t> fans;
    for (uint32_t t : edited)
        for (uint32_t f : mTopology.tile(t).fans)
            if (mTopology.fan(f).kind == FanKind::Extraordinary) fans.push_back(f);
    sortUnique(fans);
    std::vector<uint32_t> changed = edited;
    for (uint32_t f : fans)
        for (const TileCorner& c : mTopology.fanCorners(f)) changed.push_back(c.tile);
    sortUnique(changed);
    // Whoever reads a changed interior: the tile itself, its neighbours
    // across edges, and every tile around its corners (diagonals).
    std::vector<uint32_t> rewritten;
    for (uint32_t t : changed) {
        const PtexTile& tile = mTopology.tile(t);
        rewritten.push_back(t);
        for (const TileEdge& e : tile.edges)
            for (uint32_t l = 0; l < e.count; ++l) rewritten.push_back(e.links[l].tile);
        for (uint32_t f : tile.fans)
            for (const TileCorner& c : mTopology.fanCorners(f)) rewritten.push_back(c.tile);
    }
    sortUnique(rewritten);
    const detail::TileStorage storage{&mTopology, mLog2Size, mFirstCoefficient, mCoefficients, mOrigins,
                                      mWidth,     mTexels};
    detail::TileDeriver deriver(storage);
    deriver.deriveInteriors(edited, fans);
    deriver.deriveOverlaps(rewritten);
    update.edited = std::move(edited);
    update.rewritten = std::move(rewritten);
    return update;
}

void DisplacementTiles::assign(std::span<const float> coefficients) {
    assert(coefficients.size() == mCoefficients.size());
    std::copy(coefficients.begin(), coefficients.end(), mCoefficients.begin());
    rebuild();
}

void DisplacementTiles::rebuild() {
    std::vector<uint32_t> all(tileCount());
    for (uint32_t t = 0; t < tileCount(); ++t) all[t] = t;
    rederive(std::move(all));
}

shader::TileSample DisplacementTiles::evaluateLevel(uint32_t tile, uint32_t level, glm::vec2 uv) const {
    assert(level < levelCount(tile));
    return shader::tsTileEvaluateLevel({mTexels.data(), mWidth}, mRecords[tile], level, uv);
}

shader::TileSample DisplacementTiles::evaluate(uint32_t tile, glm::vec2 uv, float samplesPerTile) const {
    return shader::tsTileEvaluate({mTexels.data(), mWidth}, mRecords[tile], uv, samplesPerTile);
}

} // namespace tessera::subdiv
