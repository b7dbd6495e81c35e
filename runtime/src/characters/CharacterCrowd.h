#pragma once
/// @file CharacterCrowd.h
/// The characters scene's population: the generated creatures, CesiumMan and
/// every --model, each walking a circle on the terrain or idling, animated on
/// the CPU (poses and skinning palettes) and handed to a backend as draw items.
/// No GPU here: the backend gets assets, boxes and per-frame items.

#include "tessera/runtime/CameraOrbit.h"
#include "tessera/runtime/CharacterAssets.h"
#include "tessera/runtime/CharacterPopulation.h"
#include "tessera/runtime/CharacterPoser.h"
#include "tessera/runtime/Options.h"
#include "tessera/core/Result.h"
#include "tessera/terrain/DrawnSurface.h"
#include "tessera/terrain/Terrain.h"

#include <memory>
#include <span>
#include <vector>

namespace tessera::runtime {

class CharacterCrowd final : public CharacterPopulation {
public:
    /// Loads the generated creatures (content/characters/froblin_<1..3>.glb,
    /// --crowd of them) and CesiumMan when the build copied it (both only
    /// when --crowd > 0), and every --model; places them on the flattest
    /// ground near the terrain's centre, each frame standing on `ground`
    /// (the terrain as drawn). A file that cannot be used is an error naming
    /// it. Both must outlive the crowd.
    static Result<std::unique_ptr<CharacterCrowd>> load(const Options& options, const terrain::Terrain& terrain,
                                                        const terrain::DrawnSurface& ground);

    CharacterAssets& assets() override { return mAssets; }
    /// Poses everybody in view at `seconds` (characters whose animated box is
    /// outside the camera's frustum are skipped) and makes this frame's draw
    /// items (levels: CharacterPoser).
    void update(double seconds, const scene::Camera& camera, const CharacterLevels& levels) override;
    std::span<const backend::CharacterDrawItem> items() const override { return mPoser.items(); }
    /// The characters drawn as one instanced crowd (null with
    /// --character-path single-pass or more creatures than a crowd mixes).
    InstancedCrowd* instancedCrowd() override { return mInstanced.get(); }
    void useInstancedCrowd(bool instanced) override { mInstancedActive = instanced && mInstanced != nullptr; }
    uint32_t instanceCapacity() const override { return uint32_t(mMembers.size()); }

    /// Where the crowd gathers (on the ground), for the camera.
    glm::vec3 site() const { return mSite; }
    /// Whether the scene holds nothing but what --model placed (no
    /// generated creatures, no CesiumMan).
    bool onlyModels() const { return mOnlyModels; }
    /// Widens the orbit to fit `box` (world) too, as for --model files
    /// (unless --orbit-distance fixes it).
    void frameAlso(const scene::Aabb& box);
    /// The characters scene's camera at `seconds`: circling the site.
    void dollyOrbit(float endDistance, double seconds) override {
        mOrbit.endDistance = endDistance;
        mOrbit.dollySeconds = seconds;
    }
    scene::CameraPose orbitPose(double seconds) const override { return mOrbit.pose(*mTerrain, seconds); }

private:
    /// Points the orbit at `bounds` (world), closer when `alone`.
    void frameBounds(const scene::Aabb& bounds, bool alone);

    struct Member {
        uint32_t asset = 0;
        int clip = -1;           ///< -1: rest pose
        float clipOffset = 0.0f; ///< seconds, so members do not step in unison
        float radius = 0.0f;     ///< 0: stands at `anchor`
        float speed = 0.0f;      ///< metres per second along the circle (sign: direction)
        float angle = 0.0f;      ///< start angle on the circle, or heading when standing
        glm::vec2 anchor{0.0f};  ///< circle centre or standing point (x, z)
    };

    struct Placement {
        glm::vec3 feet{0.0f};
        float heading = 0.0f;
    };

    CharacterCrowd() = default;
    /// Where member `m` stands and faces at `seconds`.
    Placement placementAt(const Member& m, double seconds) const;
    /// Every member an instance, and the LOD manager's selection.
    void updateInstances(double seconds, const scene::Camera& camera, const CharacterLevels& levels);
    void populate(const Options& options, uint32_t froblins, uint32_t cesium, uint32_t firstModel);
    /// Points the orbit at the --model files from `firstModel` on so that
    /// they fit the view whatever their units (unless --orbit-distance).
    void frameModels(uint32_t firstModel);

    const terrain::Terrain* mTerrain = nullptr;
    const terrain::DrawnSurface* mGround = nullptr;
    CharacterAssets mAssets;
    CharacterPoser mPoser;
    std::unique_ptr<InstancedCrowd> mInstanced;
    bool mInstancedActive = false;
    std::vector<Member> mMembers;
    glm::vec3 mSite{0.0f};
    CameraOrbit mOrbit;
    bool mOnlyModels = false;
    bool mOrbitFixed = false;    ///< --orbit-distance
    scene::Aabb mFramed;         ///< what the orbit fits (world)
};

} // namespace tessera::runtime
