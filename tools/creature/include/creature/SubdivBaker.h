#pragma once
/// @file SubdivBaker.h
/// Bakes a sculpt onto a character's cage taken as a Catmull-Clark surface
/// (the second paper, Niessner and Loop): tile displacement coefficients
/// (subdiv::DisplacementTiles) such that limit point + unit limit normal * D
/// lies on the sculpt, written as the .cctiles file beside the .glb
/// (subdiv/CageTiles.h). Also measures how far the displaced surface lands
/// from the sculpt, and the same for the planar bake, so the two papers'
/// versions of one creature can be compared (docs/SUBDIV.md).

#include "creature/SculptMesh.h"
#include "tessera/character/CharacterAsset.h"
#include "tessera/core/Result.h"
#include "tessera/subdiv/CageTiles.h"

#include <cstdint>
#include <string>

namespace tessera::creature {

struct SubdivBakeOptions {
    /// Rays search this far (model units) along both sides of the limit
    /// normal and keep the sculpt hit nearest the limit surface. Wider than
    /// the planar bake's envelope: the limit surface shrinks away from the
    /// cage in convex places (ear tips, fingers).
    float searchDistance = 0.1f;
    /// Level-0 coefficients per square model unit to aim at (the planar
    /// map's covered texels over the cage's area, so both bakes hold about
    /// as much detail); 0 takes `log2Size`.
    double texelsPerArea = 0.0;
    /// Tile size of every sub-face (quad tiles get one more) when
    /// texelsPerArea is 0; 1 .. 8.
    uint32_t log2Size = 3;
    /// Error samples per ptex face side (the planar bake gets the same
    /// density per cage triangle: a triangle is three ptex faces).
    uint32_t measureGrid = 6;
    uint32_t threads = 0; ///< 0: every hardware thread; the output is the same for any count
};

/// Distances from a displaced surface to the sculpt, model units, measured
/// along the displacement direction (the nearest sculpt hit within the
/// search distance on either side, as the bake itself looks for it), over
/// samples spread evenly in every face's parameter domain.
struct SurfaceError {
    double rms = 0.0;
    double max = 0.0;
    uint64_t samples = 0;
    uint64_t unmeasured = 0; ///< samples whose ray found no sculpt (left out of rms and max)
};

struct SubdivBakeStats {
    uint32_t controlVertices = 0; ///< after welding the seams
    uint32_t ptexFaces = 0;       ///< tiles: three per cage triangle
    uint32_t patches = 0;
    uint32_t tileLog2Size = 0;    ///< of the sub-faces
    uint64_t coefficients = 0;
    uint64_t misses = 0;          ///< texel-centre rays that found no sculpt
    uint64_t missesFromNeighbours = 0; ///< of them, filled from neighbouring texels of the tile
    uint64_t missesZero = 0;      ///< of them, left at 0 (a tile without any hit)
    uint32_t conversionRounds = 0;
    bool converged = false;
    SurfaceError subdiv;          ///< the displaced Catmull-Clark surface (16-bit coefficients, level 0)
    SurfaceError subdivBase;      ///< the limit surface without displacement
    SurfaceError planar;          ///< the planar bake as the asset holds it (no samples without a map)
    uint64_t fileBytes = 0;
};

struct SubdivBakeResult {
    subdiv::CageTiles file;
    SubdivBakeStats stats;
};

/// Welds `asset.cage` (subdiv::weldTriangleCage), builds its Catmull-Clark
/// surface and one tile per ptex face, casts a ray from the limit point
/// along the unit limit normal at every level-0 texel centre, fills misses
/// from neighbouring texels of the same tile (0 in a tile without hits),
/// converts the samples to coefficients (subdiv::convertDisplacement),
/// quantizes them to 16 bits, and measures the error of the result and of
/// `asset.displacement` (when it has one). The same inputs give the same
/// bytes for any thread count. `name` labels errors (the .glb's name):
/// a cage that does not weld or refine, an empty sculpt, options out of range.
Result<SubdivBakeResult> bakeSubdivDisplacement(const character::CharacterAsset& asset, const SculptMesh& sculpt,
                                                const SubdivBakeOptions& options, const std::string& name);

} // namespace tessera::creature
