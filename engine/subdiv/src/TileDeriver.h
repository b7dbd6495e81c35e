#pragma once
/// @file TileDeriver.h
/// Derives DisplacementTiles' texture from its coefficients: the levels'
/// interiors (level 0 the coefficients, each further level the Haar average
/// of the one above), the 2x2 corner averages at extraordinary fans, and
/// the overlaps. Works on any set of tiles, reading only what the rules
/// read, so an incremental update computes exactly what a full one does.

#include "tessera/subdiv/PtexTopology.h"

#include <cstdint>
#include <span>
#include <unordered_map>

#include <glm/glm.hpp>

namespace tessera::subdiv::detail {

/// Views of DisplacementTiles' arrays.
struct TileStorage {
    const PtexTopology* topology = nullptr;
    std::span<const uint8_t> log2Size;
    std::span<const size_t> firstCoefficient;
    std::span<const float> coefficients;
    std::span<const glm::uvec2> origins;
    uint32_t width = 0;
    std::span<float> texels;
};

class TileDeriver {
public:
    explicit TileDeriver(const TileStorage& storage);

    /// Recomputes every level's interior of `tiles` and the corner averages
    /// of `fans` (extraordinary ones; every such fan at a corner of `tiles`
    /// must be among them), finest resolution first: a level's interior and
    /// averages read only finer levels, already final.
    void deriveInteriors(std::span<const uint32_t> tiles, std::span<const uint32_t> fans);
    /// Recomputes every level's overlap of `tiles` from the interiors (the
    /// interiors of every tile must be final).
    void deriveOverlaps(std::span<const uint32_t> tiles);

    /// The level of `tile` at a shared resolution, or -1.
    int levelAt(uint32_t tile, uint32_t resolution) const;

private:
    uint32_t sizeOf(uint32_t tile, uint32_t level) const { return (1u << mStorage.log2Size[tile]) >> level; }
    uint32_t resolutionOf(uint32_t tile, uint32_t level) const;
    float& at(uint32_t tile, uint32_t level, uint32_t x, uint32_t y);
    float at(uint32_t tile, uint32_t level, uint32_t x, uint32_t y) const;
    /// Interior texel (x, y) (1-based) of level `level` before any corner
    /// average: the coefficient, or the mean of the four texels above it.
    float underived(uint32_t tile, uint32_t level, uint32_t x, uint32_t y) const;
    void averageFan(uint32_t fan, uint32_t resolution);

    // Overlaps are computed as functions of interiors alone, never from
    // stored overlaps, so neither the order tiles are derived in nor which
    // tiles are derived changes a value.

    /// Texel (x, y) of a level: stored if interior, overlapValue if not.
    float texelValue(uint32_t tile, uint32_t level, uint32_t x, uint32_t y);
    /// The texel centred at `uv` (its level's grid; overlaps included).
    float texelAtPoint(uint32_t tile, uint32_t level, glm::dvec2 uv);
    /// An overlap texel by the format's rules: the neighbour's texel at the
    /// same resolution, the averaged corner next to an extraordinary fan,
    /// linear extrapolation across a boundary.
    float overlapValue(uint32_t tile, uint32_t level, uint32_t x, uint32_t y);
    /// A tile's texel centred at `uv` at a shared resolution, also one it
    /// lacks: finer ones refined from level 0 by quadratic B-spline
    /// subdivision (the same spline, at the finer knots), the one below
    /// its coarsest the mean of its 2x2 level. So every tile reading a
    /// texel of a third tile (a diagonal, a quad past a T-junction) reads
    /// the same value, whatever levels that tile has.
    float virtualTexel(uint32_t tile, uint32_t resolution, glm::dvec2 uv);
    float refined(uint32_t tile, uint32_t resolution, uint32_t x, uint32_t y);
    /// Linear extrapolation across `edge` at its parameter t: twice the
    /// texel half a texel inside minus the one a texel and a half inside.
    float extrapolate(uint32_t tile, uint32_t level, uint32_t edge, double t);

    TileStorage mStorage;
    uint32_t mMaxResolution = 1;
    /// refined()'s results, per (tile, resolution, x, y); refinement near an
    /// edge reads the same coarser texels again and again.
    std::unordered_map<uint64_t, float> mRefined;
};

} // namespace tessera::subdiv::detail
