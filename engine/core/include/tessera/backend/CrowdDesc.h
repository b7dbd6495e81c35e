#pragma once
/// @file CrowdDesc.h
/// An instanced crowd as the host hands it to a backend: the creatures it
/// mixes and their baked clips at creation, then every frame the agents as
/// instances and the LOD manager's parameters. The backend culls and bins
/// the instances into LOD tiers on the GPU with its generation's technique
/// and draws each tier instanced (docs/CROWD.md, section 6).

#include "tessera/shaders/CrowdInstance.h"
#include "tessera/backend/Handles.h"

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace tessera::character {
struct BakedAnimation;
struct CageMesh;
struct ImpostorAtlas;
} // namespace tessera::character

namespace tessera::backend {

struct CrowdTag;
/// A crowd made with Backend::createCrowd.
using CrowdHandle = Handle<CrowdTag>;

/// One creature of a crowd.
struct CrowdCharacterDesc {
    /// The character made with createCharacter: its cage, maps and box.
    CharacterHandle character;
    /// Its cage (character::CharacterAsset::cage, as given to
    /// createCharacter) and far mesh (character::CharacterAsset::farMesh;
    /// same bindings as the cage), for the middle and far tiers' baked
    /// vertex animation. Must outlive createCrowd only.
    const character::CageMesh* cage = nullptr;
    const character::CageMesh* farMesh = nullptr;
    /// The middle tier's triangles as indices into the cage's vertices (a
    /// simplified cage, lod::LodPolicy::middleMeshTriangles); empty: the
    /// cage's own. Must outlive createCrowd only.
    std::span<const uint32_t> middleIndices;
    /// The far tier's shadow casters' triangles as indices into the far
    /// mesh's vertices (a simplified far mesh, lod::LodPolicy::
    /// farCasterTriangles); empty: the far mesh's own. Must outlive
    /// createCrowd only.
    std::span<const uint32_t> farCasterIndices;
    /// The impostor tier's images (character::bakeImpostors; one layer per
    /// clip of this creature and baked phase, in the clips' order within
    /// `CrowdDesc::animation`). Required. Must outlive createCrowd only.
    const character::ImpostorAtlas* impostor = nullptr;
    /// Near-tier levels per projected pixel (lod::LodCharacter::levelPerPixel).
    float levelPerPixel = 0.01f;
};

struct CrowdDesc {
    /// At most TS_CROWD_MAX_CHARACTERS; instance `ids.y` indexes it.
    std::span<const CrowdCharacterDesc> characters;
    /// Every creature's clips in one buffer (character::combine, in the
    /// order of `characters`); instance `ids.z` is a global clip index.
    const character::BakedAnimation* animation = nullptr;
    /// The most instances a frame will have.
    uint32_t maxInstances = 0;
    /// The most instance ids (state is kept per id): ids are below it.
    uint32_t maxIds = 0;
    /// Compressed-cage slots for the near tier (its instances and fading
    /// copies): lod::LodBudget::maxNearInstances, at most.
    uint32_t nearSlots = 64;
};

/// One frame of a crowd.
struct CrowdDrawInfo {
    std::span<const shader::CrowdInstance> instances;
    /// lod::LodFrame::params for this frame's view.
    shader::CrowdLodParams lod{};
    /// The horizon's grid (lod::LodView::occluders): `lod.occluder.w`
    /// squared lowest drawn heights, row by row; empty with no occlusion.
    std::span<const float> occluders;
    bool displacement = true; ///< displace the near tier
    bool lodColors = false;   ///< tint by tier
};

/// What the GPU drew in one frame, per tier (fading copies included).
struct CrowdTierCounts {
    std::array<uint32_t, TS_LOD_TIERS> instances{};
    std::array<uint64_t, TS_LOD_TIERS> triangles{}; ///< before clipping; near: after tessellation
};

/// A blocking read of the last drawn frame's lists, for tests against the
/// CPU reference: per tier, the instance indices drawn (fading copies
/// included, each list in the GPU's append order).
struct CrowdTiers {
    std::array<std::vector<uint32_t>, TS_LOD_TIERS> instances;
};

} // namespace tessera::backend
