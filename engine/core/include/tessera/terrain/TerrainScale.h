#pragma once
/// @file TerrainScale.h
/// How normalised height-map samples map to metres in the world.

namespace tessera::terrain {

/// World-space scale of a height field.
///
/// Sample (i, j) lies at world x = i * horizontalSpacing, z = j * horizontalSpacing
/// (right-handed, +Y up, the terrain in XZ). A sample value v in 0..65535 stands
/// for a height of y = v / 65535 * heightScale metres. The defaults give the
/// 2048x2048 content map an extent of 8188 m (2047 spacings) and 600 m of relief.
struct TerrainScale {
    float horizontalSpacing = 4.0f; ///< Metres between neighbouring samples along X and Z.
    float heightScale = 600.0f;     ///< Metres at sample value 65535 (value 0 is y = 0).
};

} // namespace tessera::terrain
