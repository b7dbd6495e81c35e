#pragma once
/// @file DisplacementTiles.h
/// The tile-based displacement of Niessner and Loop (section 4) on the CPU:
/// per ptex face a biquadratic B-spline D over [0, 1]^2, its coefficients
/// with a one-texel overlap, a mip pyramid, all tiles packed into one float
/// texture, and a 16-byte record per tile or patch; exactly the arrays a
/// shader reads (layout and lookup in tessera/shaders/DisplacementTile.h,
/// which the evaluation here runs too). docs/SUBDIV.md, "Tiles", has the
/// figures.
///
/// The coefficients a user sets (level 0's interior, tileSize^2 a tile) are
/// kept apart from the texture, which is derived from them:
///   - levels: Haar averages of the level above, down to 2x2;
///   - corner averages: at every extraordinary fan (section 4.2) the 2x2
///     corner blocks of all its tiles that have the level take the mean of
///     their corner coefficients, so D is equal and flat (dD = 0) there;
///   - overlaps: per level, the neighbour's texels at the same resolution
///     (a quad's level r meets a sub-face's level r - 1: sub-faces are half
///     as wide along a base edge), corners from the diagonal tile; where
///     that tile lacks the level, from a virtual one (its level 0 refined
///     by B-spline subdivision, or its 2x2 level averaged), so every tile
///     reading a third tile's texel reads the same value; across a
///     boundary, linear extrapolation of the tile's own texels;
///   - level limits (section 4.4): per fan, the finest level all its tiles
///     share (the smallest k + scale around it, scale 1 for sub-faces), and
///     per tile corner the difference to it, so the interpolated limit is
///     equal from both sides of every edge. The paper words the base value
///     as the highest resolution around the vertex; that makes the limit
///     differ across edges between tiles of different sizes (the tests show
///     it), the lowest does not. Likewise the coarsest level is raised to
///     resolution 2 at quad corners a sub-face touches.
/// Editing changes coefficients and rederives only the tiles that can
/// change, with the same arithmetic, so the texture stays bit-identical to
/// a full rebuild.

#include "tessera/core/Result.h"
#include "tessera/subdiv/PatchData.h"
#include "tessera/subdiv/PtexTopology.h"

#include "tessera/shaders/DisplacementTile.h"

#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace tessera::subdiv {

/// One coefficient to set: level-0 interior texel (x, y), 0-based, of a tile.
struct CoefficientEdit {
    uint32_t tile = 0;
    uint32_t x = 0, y = 0;
    float value = 0.0f;
};

/// What an edit rederived.
struct TileUpdate {
    std::vector<uint32_t> edited;    ///< tiles whose coefficients changed
    std::vector<uint32_t> rewritten; ///< tiles whose texels were recomputed (to upload), sorted
};

class DisplacementTiles {
public:
    /// Tiles of `log2Sizes[t]` (k, tileSize = 2^k, 1 <= k <= 12) per tile of
    /// `topology`, coefficients 0. Errors: a count or k out of range; a
    /// quad tile of k = 1 sharing a vertex with a sub-face tile (a sub-face's
    /// coarsest level, 2x2, meets a quad's 4x4, so the quad has no level to
    /// match it: see legalLog2Sizes); a texture past 65535 texels a side.
    static Result<DisplacementTiles> create(PtexTopology topology, std::vector<uint8_t> log2Sizes);
    /// Quads k, sub-faces k - 1 (the same texel size along base edges),
    /// made legal.
    static std::vector<uint8_t> uniformLog2Sizes(const PtexTopology& topology, uint32_t quadLog2Size);
    /// `log2Sizes` clamped to 1..12, with quad tiles that share a vertex
    /// with a sub-face tile raised to 2 or more.
    static std::vector<uint8_t> legalLog2Sizes(const PtexTopology& topology, std::vector<uint8_t> log2Sizes);

    const PtexTopology& topology() const { return mTopology; }
    uint32_t tileCount() const { return mTopology.tileCount(); }
    uint32_t log2Size(uint32_t tile) const { return mLog2Size[tile]; }
    uint32_t tileSize(uint32_t tile) const { return 1u << mLog2Size[tile]; }
    /// Levels of a tile: log2Size (level l is tileSize >> l a side).
    uint32_t levelCount(uint32_t tile) const { return mLog2Size[tile]; }
    /// A tile's level l in units shared across edges: log2 of its size per
    /// base edge (log2Size - l, plus 1 for sub-faces).
    uint32_t resolutionOf(uint32_t tile, uint32_t level) const;

    /// The coefficients set (level 0's interior, row after row, tileSize^2).
    std::span<const float> coefficients(uint32_t tile) const;

    /// The packed texture (R32F), row-major.
    uint32_t textureWidth() const { return mWidth; }
    uint32_t textureHeight() const { return mHeight; }
    std::span<const float> texels() const { return mTexels; }
    /// Texel (x, y) of a tile's level, x and y in 0 .. (tileSize >> level) + 1.
    float texel(uint32_t tile, uint32_t level, uint32_t x, uint32_t y) const;
    /// The texture origin of the tile's level 0.
    glm::uvec2 tileOrigin(uint32_t tile) const;

    /// One record per tile (domain offset 0, domain level 0).
    std::span<const shader::TileRecord> tileRecords() const { return mRecords; }
    /// One record per patch: its tile's, with its domain offset and level
    /// from its PatchParam.
    std::vector<shader::TileRecord> patchRecords(std::span<const Patch> patches) const;
    /// The finest resolution (resolutionOf units) all tiles around a fan
    /// share: what tsTileMaxResolution reaches at that point.
    uint32_t fanResolution(uint32_t fan) const { return mFanResolution[fan]; }

    /// Sets a rectangle of a tile's coefficients (`values` row after row,
    /// size.x * size.y) and rederives what depends on them.
    TileUpdate setCoefficients(uint32_t tile, glm::uvec2 origin, glm::uvec2 size, std::span<const float> values);
    /// Sets any coefficients (a brush stroke over several tiles) and
    /// rederives what depends on them: the edited tiles' levels, the corner
    /// averages at their extraordinary corners, and the overlaps of every
    /// tile reading a changed texel.
    TileUpdate edit(std::span<const CoefficientEdit> edits);
    /// Replaces every coefficient (tile after tile, each tileSize^2 row
    /// after row: allCoefficients()' layout) and rederives everything.
    void assign(std::span<const float> coefficients);
    /// Every tile's coefficients, tile after tile.
    std::span<const float> allCoefficients() const { return mCoefficients; }
    /// Where a tile's coefficients start in allCoefficients().
    size_t firstCoefficient(uint32_t tile) const { return mFirstCoefficient[tile]; }
    /// Rederives the whole texture from the coefficients.
    void rebuild();

    /// D at tile (u, v) from one level (the shared lookup).
    shader::TileSample evaluateLevel(uint32_t tile, uint32_t level, glm::vec2 uv) const;
    /// D at tile (u, v) for a sampling density (tsTileEvaluate: two levels
    /// blended, clamped to the tile's limit there).
    shader::TileSample evaluate(uint32_t tile, glm::vec2 uv, float samplesPerTile) const;

private:
    DisplacementTiles() = default;
    TileUpdate rederive(std::vector<uint32_t> edited);

    PtexTopology mTopology;
    std::vector<uint8_t> mLog2Size;
    std::vector<size_t> mFirstCoefficient; ///< per tile, and the total last
    std::vector<float> mCoefficients;
    std::vector<glm::uvec2> mOrigins;
    std::vector<uint8_t> mFanResolution;
    uint32_t mWidth = 0, mHeight = 0;
    std::vector<float> mTexels;
    std::vector<shader::TileRecord> mRecords;
};

} // namespace tessera::subdiv
