#pragma once
/// @file TerrainDetailTextures.h
/// Loads the terrain's detail textures (content/terrain/detail_<material>.png,
/// made by tessera-texgen at build time) for backend::TerrainDesc.

#include "tessera/core/ImageFile.h"
#include "tessera/core/Result.h"

#include <string>
#include <vector>

namespace tessera::runtime {

/// The four textures in TerrainDesc's layer order (grass, dirt, rock, snow),
/// found like the height map (locateContent). A missing, unreadable or
/// misshapen file fails with a message naming it.
Result<std::vector<Rgba8Image>> loadTerrainDetailTextures(const std::string& contentDir);

} // namespace tessera::runtime
