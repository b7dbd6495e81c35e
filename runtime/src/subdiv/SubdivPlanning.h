#pragma once
/// @file SubdivPlanning.h
/// What the demo's two kinds of Catmull-Clark surfaces (SubdivModels: the
/// .obj shapes; SubdivCharacters: the creatures) share each frame: the view
/// and settings the level of detail plans with, the frame's triangle budget
/// shared between surfaces, and the tiles as a backend takes them.

#include "tessera/runtime/Options.h"
#include "tessera/backend/SubdivDesc.h"
#include "tessera/scene/Camera.h"
#include "tessera/subdiv/DisplacementTiles.h"
#include "tessera/subdiv/SubdivLod.h"

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace tessera::runtime {

/// The view of `camera` on a `viewportHeight`-pixel target.
subdiv::SubdivView subdivView(const scene::Camera& camera, uint32_t viewportHeight);

/// The settings from the options: the backend's `levelCap`, and `level` as
/// the fixed level (0: screen-space levels).
subdiv::SubdivLodSettings subdivSettings(const SubdivOptions& options, float levelCap, float level);

/// Plans `count` surfaces with `plan(i, share)`; over `budget` triangles
/// (0: none), each surface's share follows what it would take alone.
std::vector<subdiv::SubdivLodFrame>
planWithinBudget(size_t count, uint64_t budget, const std::function<subdiv::SubdivLodFrame(size_t, uint64_t)>& plan);

/// `tiles` and their `records` as createSubdiv and updateSubdivTiles take them.
backend::SubdivTileData subdivTileData(const subdiv::DisplacementTiles& tiles, std::span<const glm::uvec4> records);

} // namespace tessera::runtime
