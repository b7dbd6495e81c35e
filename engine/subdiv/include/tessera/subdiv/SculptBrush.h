#pragma once
/// @file SculptBrush.h
/// A sculpt brush over a displaced Catmull-Clark surface (issue 14, item 6):
/// a dab raises or lowers the displacement D around a point of the surface
/// with a smooth falloff, through DisplacementTiles::edit, which rederives
/// only the touched tiles, their levels, the corner averages at their
/// extraordinary corners and the neighbours' overlaps. uploadRects then
/// names the texel rectangles a backend re-uploads (updateSubdivTiles), so
/// the next frame draws the stroke, its normals derived from the same tiles.
/// CPU only; the brush works in the surface's object space (rest pose).

#include "tessera/subdiv/DisplacementTiles.h"
#include "tessera/subdiv/SubdivSurface.h"

#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace tessera::subdiv {

/// One dab, in the surface's object space.
struct SculptDab {
    glm::vec3 centre{0.0f};
    float radius = 0.1f;
    /// Added to D at the centre (object units; negative lowers), fading
    /// smoothly to 0 at the radius: amount * (1 - (d / radius)^2)^2.
    float amount = 0.01f;
};

class SculptBrush {
public:
    /// Places every coefficient of `tiles` on `surface`'s limit surface
    /// (the B-spline coefficient (x, y) of a tile of n sits at ptex
    /// ((x + 0.5) / n, (y + 0.5) / n) of its face). Hole faces get no
    /// positions and are never edited.
    SculptBrush(const SubdivSurface& surface, const DisplacementTiles& tiles);

    /// Applies one dab to `tiles` (the tiles this brush was made for).
    TileUpdate apply(DisplacementTiles& tiles, const SculptDab& dab) const;

    /// The limit point nearest `p` among the coefficients' positions.
    glm::vec3 nearestSurfacePoint(glm::vec3 p) const;

    /// Texel rectangles (x, y, width, height) of the rewritten tiles, all
    /// their levels and overlaps: what a backend re-uploads.
    static std::vector<glm::uvec4> uploadRects(const DisplacementTiles& tiles, const TileUpdate& update);

private:
    struct TileSamples {
        size_t first = 0; ///< into mPositions (allCoefficients' layout)
        uint32_t size = 0;
        glm::vec3 lo{0.0f}, hi{0.0f}; ///< box of the tile's positions
        bool valid = false;           ///< false for holes
    };
    std::vector<glm::vec3> mPositions;
    std::vector<TileSamples> mTiles;
};

} // namespace tessera::subdiv
