#pragma once
/// @file ImpostorBaker.h
/// Bakes a character's impostor atlas (ImpostorAtlas.h, layout in
/// shaders/CrowdImpostor.h) on the CPU: its cage skinned at every clip's
/// baked phases and drawn orthographically from each view cell's direction.
/// Run by the content build (tools/impostor, `<name>.impostor` beside the
/// `.glb`) and at load time for a model that has no such file
/// (docs/CROWD.md 6.9).

#include "tessera/character/BakedAnimation.h"
#include "tessera/character/CharacterAsset.h"
#include "tessera/character/ImpostorAtlas.h"
#include "tessera/scene/Aabb.h"

#include <cstdint>

namespace tessera::character {

/// How bakeImpostors samples and spreads its work.
struct ImpostorBakeSettings {
    /// How the crowd bakes the character's clips (runtime::InstancedCrowd
    /// uses the defaults): the baker poses the cage exactly as the crowd's
    /// baked animation does at each phase (evaluateBakedPalette), and a
    /// clip loops when these settings loop it.
    BakeSettings animation{};
    /// Threads (0: every hardware thread). The bytes do not depend on it.
    uint32_t threads = 0;
};

/// The sphere an atlas's cells frame, in model space: centre (0, centreY, 0)
/// and radius, as the crowd's instance sphere (runtime SimulatedCrowd and
/// CharacterCrowd) from animatedBounds(asset) with its default arguments:
/// centreY = box.center().y, radius = length(box.extents()) +
/// length(box.center().xz). Zero radius for an empty cage.
struct ImpostorSphere {
    float centreY = 0.0f;
    float radius = 0.0f;
};
ImpostorSphere impostorSphere(const CharacterAsset& asset);
/// The same from the box animatedBounds(asset) returned (for a caller that
/// has it already).
ImpostorSphere impostorSphere(const scene::Aabb& animatedBox);

/// The layers an atlas of a character with `clips` clips has:
/// clips * TS_IMPOSTOR_PHASES, or TS_IMPOSTOR_PHASES (the rest pose) with none.
uint32_t impostorLayerCount(uint32_t clips);

/// The atlas of `asset`: for every clip (asset.clips order; the rest pose
/// alone for a character without clips) and phase k (a looping clip's
/// phase k / PHASES, any other's k / (PHASES - 1)), the cage skinned by the
/// crowd's baked palette at that phase and drawn into each of the
/// TS_IMPOSTOR_VIEWS^2 cells from tsImpostorCellDirection, framed by
/// impostorSphere (tsImpostorProject, tsImpostorCellTexel), z-buffered.
///
/// Per texel, 2 x 2 samples: coverage in alpha; the base colour (bilinear,
/// clamp to edge, from asset.baseColor box-filtered to about one texel per
/// sample; grey 150 without one, as the meshes) averaged over the covered
/// samples in the stored sRGB values, as the GPU filters the map (UNORM);
/// the interpolated skinned normal averaged and normalised. Colour and
/// normal are then dilated 4 texels into each cell's uncovered texels and
/// the rest of the cell takes its mean, so filtering never pulls in black;
/// each mip is a 2 x 2 box of the one above, colour and normal weighted by
/// coverage. The same bytes on every run and for any thread count.
/// An empty atlas for a cage without triangles.
ImpostorAtlas bakeImpostors(const CharacterAsset& asset, const ImpostorBakeSettings& settings = {});

} // namespace tessera::character
