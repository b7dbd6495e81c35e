#pragma once
/// @file CharacterAssets.h
/// The characters a scene draws, loaded once: each asset with what drawing it
/// needs (compression box, mean edge, the crowd's impostor atlas) and, once
/// uploaded, its backend handle. Shared by the characters scene and the
/// crowd scene.

#include "tessera/backend/CharacterDesc.h"
#include "tessera/character/CharacterAsset.h"
#include "tessera/character/ImpostorAtlas.h"
#include "tessera/core/Result.h"
#include "tessera/scene/Aabb.h"

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace tessera::runtime {

/// One loaded asset and what drawing it needs.
struct CrowdAsset {
    std::string file;
    character::CharacterAsset asset;
    scene::Aabb box;       ///< compression box (character::animatedBounds)
    float meanEdge = 0.0f; ///< mean cage edge length, model units: drives the level
    /// The crowd's impostor tier's images: the content build's
    /// `<file without .glb/.gltf>.impostor` when it is this asset's (this
    /// build's layout, a layer per phase of each clip, the same sphere),
    /// else baked at load (character::bakeImpostors).
    character::ImpostorAtlas impostor;
};

class CharacterAssets {
public:
    /// How many generated creatures the build makes (content/characters/froblin_1..3.glb).
    static constexpr uint32_t kFroblinSeeds = 3;

    /// Loads `file` (any glTF the loader accepts) and its impostor atlas. A
    /// file that cannot be used is an error naming it; an impostor file
    /// beside it that cannot be used is a warning naming it, and a bake.
    Status add(const std::string& file);
    /// Loads the first `count` generated creatures (at most kFroblinSeeds)
    /// from the content directory (--content, see locateContent).
    Status addFroblins(const std::string& contentDir, uint32_t count);

    std::span<const CrowdAsset> all() const { return mAssets; }
    const CrowdAsset& operator[](size_t index) const { return mAssets[index]; }
    size_t size() const { return mAssets.size(); }
    bool empty() const { return mAssets.empty(); }

    /// The backend's handles, in all() order (RenderSession::createCharacters).
    void bind(std::vector<backend::CharacterHandle> handles) { mHandles = std::move(handles); }
    /// The handle of asset `index`, or an invalid one before bind().
    backend::CharacterHandle handle(size_t index) const {
        return index < mHandles.size() ? mHandles[index] : backend::CharacterHandle{};
    }

private:
    std::vector<CrowdAsset> mAssets;
    std::vector<backend::CharacterHandle> mHandles;
};

/// The clip of `asset` named `name`, else its first clip, else -1 (rest pose).
int findClip(const character::CharacterAsset& asset, const char* name);

} // namespace tessera::runtime
