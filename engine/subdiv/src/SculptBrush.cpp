#include "tessera/subdiv/SculptBrush.h"

#include "tessera/shaders/DisplacementTile.h"

#include <algorithm>
#include <limits>

namespace tessera::subdiv {

SculptBrush::SculptBrush(const SubdivSurface& surface, const DisplacementTiles& tiles) {
    mPositions.resize(tiles.allCoefficients().size());
    mTiles.resize(tiles.tileCount());
    for (uint32_t t = 0; t < tiles.tileCount(); ++t) {
        TileSamples& s = mTiles[t];
        s.first = tiles.firstCoefficient(t);
        s.size = tiles.tileSize(t);
        s.lo = glm::vec3(std::numeric_limits<float>::max());
        s.hi = -s.lo;
        // Tile t is ptex face t (PtexTopology numbers them alike).
        for (uint32_t y = 0; y < s.size; ++y)
            for (uint32_t x = 0; x < s.size; ++x) {
                const glm::dvec2 uv((x + 0.5) / s.size, (y + 0.5) / s.size);
                const std::optional<LimitPoint> p = surface.evaluatePtex(t, uv);
                if (!p) continue;
                const glm::vec3 position(p->position);
                mPositions[s.first + size_t(y) * s.size + x] = position;
                s.lo = glm::min(s.lo, position);
                s.hi = glm::max(s.hi, position);
                s.valid = true;
            }
    }
}

TileUpdate SculptBrush::apply(DisplacementTiles& tiles, const SculptDab& dab) const {
    std::vector<CoefficientEdit> edits;
    const float r2 = dab.radius * dab.radius;
    const std::span<const float> values = tiles.allCoefficients();
    for (uint32_t t = 0; t < mTiles.size(); ++t) {
        const TileSamples& s = mTiles[t];
        if (!s.valid) continue;
        // The tile's box, grown by the radius, must hold the centre.
        const glm::vec3 nearest = glm::clamp(dab.centre, s.lo, s.hi);
        if (glm::dot(nearest - dab.centre, nearest - dab.centre) > r2) continue;
        for (uint32_t y = 0; y < s.size; ++y)
            for (uint32_t x = 0; x < s.size; ++x) {
                const size_t i = s.first + size_t(y) * s.size + x;
                const glm::vec3 d = mPositions[i] - dab.centre;
                const float q = glm::dot(d, d) / r2;
                if (q >= 1.0f) continue;
                const float falloff = (1.0f - q) * (1.0f - q);
                edits.push_back({t, x, y, values[i] + dab.amount * falloff});
            }
    }
    if (edits.empty()) return {};
    return tiles.edit(edits);
}

glm::vec3 SculptBrush::nearestSurfacePoint(glm::vec3 p) const {
    glm::vec3 best = p;
    float bestDistance = std::numeric_limits<float>::max();
    for (const TileSamples& s : mTiles) {
        if (!s.valid) continue;
        for (size_t i = s.first; i < s.first + size_t(s.size) * s.size; ++i) {
            const float d = glm::dot(mPositions[i] - p, mPositions[i] - p);
            if (d < bestDistance) bestDistance = d, best = mPositions[i];
        }
    }
    return best;
}

std::vector<glm::uvec4> SculptBrush::uploadRects(const DisplacementTiles& tiles, const TileUpdate& update) {
    std::vector<glm::uvec4> rects;
    rects.reserve(update.rewritten.size());
    for (uint32_t t : update.rewritten) {
        const glm::uvec2 origin = tiles.tileOrigin(t);
        const glm::uvec2 footprint = shader::tsTileFootprint(tiles.log2Size(t));
        rects.emplace_back(origin, footprint);
    }
    return rects;
}

} // namespace tessera::subdiv
