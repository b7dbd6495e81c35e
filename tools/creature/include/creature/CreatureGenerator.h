#pragma once
/// @file CreatureGenerator.h
/// A procedural Froblin-like creature: a goblin with big ears, a hunched body,
/// limbs and head features, deterministic by seed.

#include "creature/SculptMesh.h"
#include "tessera/character/CharacterAsset.h"
#include "tessera/character/FarMesh.h"

#include <cstdint>
#include <functional>
#include <optional>

namespace tessera::creature {

/// What to make.
struct CreatureOptions {
    uint32_t seed = 1;
    /// Minimum triangle count of the high-resolution sculpt.
    uint32_t sculptTriangles = 1'000'000;
    /// Target triangle count of the control cage (about 5K, as the paper's 5.2K).
    uint32_t cageTriangles = 5'000;
    /// Size of the square base colour texture (tests use small ones).
    uint32_t baseColorSize = 1024;
};

/// The two versions of one creature, in the same bind-pose model space
/// (metres, +Y up, facing +Z, feet at y = 0).
struct Creature {
    /// The cage with UVs, tangents, skin weights, skeleton and clips
    /// ("walk", "idle"); no maps yet (the baker makes them).
    character::CharacterAsset asset;
    /// The detailed sculpt (wrinkles, warts, bumps; eyes, mouth, teeth and
    /// gear) the maps are baked from.
    SculptMesh sculpt;
    /// How the far mesh (`asset.farMesh`) was simplified from the cage: its
    /// method and error, for the report.
    std::optional<character::FarMesh> far;
};

/// Progress callback: a stage name and its fraction done in [0, 1].
using ProgressFn = std::function<void(const char* stage, float fraction)>;

/// Makes one creature. The same options give the same bytes on every run.
///
/// Stages (progress names): "shape" extracts the base distance field's
/// surface without its millimetre detail (marching tetrahedra, ~7 mm grid); "cage" simplifies it to the
/// target (meshoptimizer), builds the UV atlas (axis-facing charts, shelf
/// packed with a 10-texel gutter at 2048), normals, tangents and skin
/// weights, then simplifies the cage into the far LOD mesh
/// (character::simplifyCage, 300 triangles); "sculpt" subdivides the cage and projects it onto the detailed
/// skin; "texture" paints the base colour into the atlas.
Creature generateCreature(const CreatureOptions& options, const ProgressFn& progress = {});

} // namespace tessera::creature
