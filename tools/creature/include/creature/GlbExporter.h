#pragma once
/// @file GlbExporter.h
/// Writes a character as a glTF 2.0 binary (.glb).

#include "tessera/character/CharacterAsset.h"
#include "tessera/core/Result.h"

#include <filesystem>

namespace tessera::creature {

/// Export choices.
struct ExportOptions {
    /// Compress the cage with KHR_draco_mesh_compression (required extension).
    bool draco = true;
    /// Draco quantisation bits (1..30) per attribute kind. A position moves
    /// by at most half a step of (largest bounding-box extent) / (2^bits - 1).
    int dracoPositionBits = 14;
    /// Octahedral normal bits; 10 bits keep normals within about a degree.
    int dracoNormalBits = 10;
    /// 16 rather than Draco's usual 12: a 2K displacement map needs UVs
    /// within a small fraction of a texel, or seam texels disagree.
    int dracoTexCoordBits = 16;
    int dracoGenericBits = 12;  ///< tangents and weights (joints are exact integers)
};

/// Writes `asset` (cage, skin, skeleton nodes, clips, base colour, normal and
/// displacement maps) to `file` as one glTF 2.0 scene: the skeleton's nodes
/// (same indices) plus one root mesh node with the skin, one triangle
/// primitive, one material, one animation per non-empty clip. Maps are
/// embedded PNGs (the displacement map 16-bit grayscale); the displacement
/// scale and bias are the material's `extras.tessera_displacement`
/// (docs/CHARACTERS.md). An `asset.farMesh` becomes an MSFT_lod level (an
/// optional extension): a second, uncompressed mesh on a node outside the
/// scene with the same skin, named in the mesh node's
/// `extensions.MSFT_lod.ids`, with `extras.MSFT_screencoverage`.
/// The same asset and options give the same bytes.
/// Fails, naming the file, on an asset that would make an invalid file or
/// on a file that cannot be written.
Result<void> exportGlb(const character::CharacterAsset& asset, const std::filesystem::path& file,
                       const ExportOptions& options = {});

} // namespace tessera::creature
