#pragma once
/// @file TerrainDesc.h
/// The terrain the host asks a backend to upload, and how to draw it.

#include <cstdint>
#include <span>

namespace tessera::terrain {
class HeightField;
}

namespace tessera::backend {

/// Upload description. The backend copies what it needs; the height field
/// stays owned by the engine (it is the CPU copy gameplay queries use).
struct TerrainDesc {
    const terrain::HeightField* heightField = nullptr;
    /// Tiles per side; tile t covers samples [tx*n, (tx+1)*n] with
    /// n = (width-1)/tilesPerSide, tx = t % tilesPerSide.
    uint32_t tilesPerSide = 16;
    /// Control-mesh quads per tile side for the untessellated (lowres) draw.
    uint32_t quadsPerTile = 32;
};

/// The paper's Table 2 modes.
enum class TerrainMode {
    LowRes,     ///< the untessellated control mesh
    Continuous, ///< one tessellation level per draw
    Adaptive,   ///< per-edge adaptive levels
};

const char* toString(TerrainMode mode);

struct TerrainDrawInfo {
    /// Indices of the tiles that survived frustum culling, in draw order.
    std::span<const uint32_t> visibleTiles;
    TerrainMode mode = TerrainMode::LowRes;
};

} // namespace tessera::backend
