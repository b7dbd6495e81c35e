#pragma once
/// @file CharacterCrowd.h
/// The characters scene's population: the generated creatures, CesiumMan and
/// every --model, each walking a circle on the terrain or idling, animated on
/// the CPU (poses and skinning palettes) and handed to a backend as draw items.
/// No GPU here: the backend gets assets, boxes and per-frame items.

#include "DemoOptions.h"
#include "tessera/backend/CharacterDesc.h"
#include "tessera/character/CharacterAsset.h"
#include "tessera/character/Pose.h"
#include "tessera/core/Result.h"
#include "tessera/scene/Aabb.h"
#include "tessera/scene/Camera.h"
#include "tessera/scene/Frustum.h"
#include "tessera/terrain/Terrain.h"

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace tessera::demo {

/// One loaded asset and what drawing it needs.
struct CrowdAsset {
    std::string file;
    character::CharacterAsset asset;
    scene::Aabb box;          ///< compression box (character::animatedBounds)
    float meanEdge = 0.0f;    ///< mean cage edge length, model units: drives the level
};

class CharacterCrowd {
public:
    /// Loads the generated creatures (content/characters/froblin_<1..3>.glb,
    /// --crowd of them) and CesiumMan when the build copied it (both only
    /// when --crowd > 0), and every --model; places them on the flattest
    /// ground near the terrain's centre. A file that cannot be used is an
    /// error naming it.
    static Result<std::unique_ptr<CharacterCrowd>> load(const DemoOptions& options, const terrain::Terrain& terrain);

    std::span<const CrowdAsset> assets() const { return mAssets; }
    /// The backend's handles, in assets() order, before the first items().
    void bind(std::vector<backend::CharacterHandle> handles) { mHandles = std::move(handles); }

    /// Poses everybody in view at `seconds` (characters whose animated box is
    /// outside the camera's frustum are skipped) and makes this frame's draw
    /// items. The
    /// level is `fixedLevel` when given, else chosen so a tessellated edge
    /// covers about kTargetEdgePixels on screen; clamped to [1, maxLevel].
    void update(double seconds, const scene::Camera& camera, uint32_t viewportHeight, float maxLevel,
                std::optional<float> fixedLevel);
    std::span<const backend::CharacterDrawItem> items() const { return mItems; }

    /// Where the crowd gathers (on the ground), for the camera.
    glm::vec3 site() const { return mSite; }
    /// The characters scene's camera at `seconds`: circling the site.
    scene::CameraPose orbitPose(double seconds) const;

    static constexpr float kTargetEdgePixels = 1.0f;

private:
    struct Member {
        uint32_t asset = 0;
        int clip = -1;          ///< -1: rest pose
        float clipOffset = 0.0f; ///< seconds, so members do not step in unison
        float radius = 0.0f;    ///< 0: stands at `anchor`
        float speed = 0.0f;     ///< metres per second along the circle (sign: direction)
        float angle = 0.0f;     ///< start angle on the circle, or heading when standing
        glm::vec2 anchor{0.0f}; ///< circle centre or standing point (x, z)
        std::unique_ptr<character::Pose> pose;
        std::vector<glm::mat4> palette;
    };

    CharacterCrowd() = default;
    Status addAsset(const std::string& file);
    void populate(const DemoOptions& options, uint32_t froblins, uint32_t cesium, uint32_t firstModel);

    const terrain::Terrain* mTerrain = nullptr;
    std::vector<CrowdAsset> mAssets;
    std::vector<Member> mMembers;
    std::vector<backend::CharacterHandle> mHandles;
    std::vector<backend::CharacterDrawItem> mItems;
    glm::vec3 mSite{0.0f};
    float mOrbitDistance = 5.0f;
};

} // namespace tessera::demo
