#pragma once
/// @file TerrainDesc.h
/// The terrain the host asks a backend to upload, and how to draw it.

#include "tessera/core/ImageFile.h"
#include "tessera/terrain/CraterSplat.h"
#include "tessera/terrain/TessellationSettings.h"

#include <cstdint>
#include <span>

namespace tessera::terrain {
class Terrain;
}

namespace tessera::backend {

using terrain::TerrainMode;

/// Upload description. The terrain stays owned by the engine (its height
/// field is the CPU copy gameplay queries use) and must outlive the backend's
/// handle: backends read its control mesh and detail errors when they change
/// (Terrain::revision()). createTerrain uploads the height field as it is
/// then, so splats still queued at that point are already in the GPU copy:
/// the host drops them (Terrain::takePendingSplats) instead of sending them.
struct TerrainDesc {
    const terrain::Terrain* terrain = nullptr;
    /// The full look's detail albedo textures (docs/LOOKS.md), sRGB RGBA8, in
    /// layer order grass, dirt, rock, snow (TS_DETAIL_*): four square images
    /// of one power-of-two size, which tile. Read during createTerrain only.
    /// Empty: the backend shades with each material's flat average colour.
    std::span<const Rgba8Image> detailTextures;
};

struct TerrainDrawInfo {
    /// Indices of the patches that survived culling (Terrain::cull), in draw order.
    std::span<const uint32_t> visiblePatches;
    /// Mode, metric and levels; maxLevel is clamped to the backend's maximum.
    terrain::TessellationSettings tessellation;
};

} // namespace tessera::backend
