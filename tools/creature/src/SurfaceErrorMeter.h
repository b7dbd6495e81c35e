#pragma once
/// @file SurfaceErrorMeter.h
/// How far a displaced surface lands from the sculpt, for both papers'
/// versions of a creature: the distance along the displacement direction to
/// the nearest sculpt hit (SubdivBaker.h, SurfaceError), at samples spread
/// evenly over every face's parameter domain. Per face partial sums, reduced
/// in face order: the same figures for any thread count.

#include "creature/Bvh.h"
#include "creature/SubdivBaker.h"
#include "tessera/character/CharacterAsset.h"
#include "tessera/subdiv/DisplacementTiles.h"
#include "tessera/subdiv/SubdivSurface.h"

#include <cstdint>

namespace tessera::creature {

/// The Catmull-Clark surface displaced by `tiles` at level 0 (or not at all
/// with `tiles` null): grid x grid samples at cell centres of every ptex face.
SurfaceError measureSubdivError(const subdiv::SubdivSurface& surface, const subdiv::DisplacementTiles* tiles,
                                const Bvh& bvh, float search, uint32_t grid, uint32_t threads);

/// The planar bake as the renderers evaluate it: the cage triangles'
/// interpolated positions displaced along the normalised interpolated
/// normal by the bilinear 16-bit map (`displacement`), grid^2 stratified
/// samples a triangle. Empty figures when the map is not R16.
SurfaceError measurePlanarError(const character::CageMesh& cage, const character::DisplacementMap& displacement,
                                const Bvh& bvh, float search, uint32_t grid, uint32_t threads);

} // namespace tessera::creature
