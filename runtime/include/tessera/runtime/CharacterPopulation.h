#pragma once
/// @file CharacterPopulation.h
/// What a scene with characters gives the frame loop: the assets to upload,
/// the frame's draw items and the camera circling them. The characters scene
/// (CharacterCrowd) and the crowd scene (SimulatedCrowd) implement it.

#include "tessera/runtime/CharacterAssets.h"
#include "tessera/runtime/CharacterPoser.h"
#include "tessera/runtime/InstancedCrowd.h"
#include "tessera/backend/CharacterDesc.h"
#include "tessera/scene/Camera.h"
#include "tessera/scene/CameraPose.h"

#include <span>
#include <vector>

namespace tessera::runtime {

class CharacterPopulation {
public:
    virtual ~CharacterPopulation() = default;

    /// The assets to upload; RenderSession::createCharacters binds their handles.
    virtual CharacterAssets& assets() = 0;
    /// Poses the characters in view of `camera` at `seconds` and makes this
    /// frame's draw items.
    virtual void update(double seconds, const scene::Camera& camera, const CharacterLevels& levels) = 0;
    virtual std::span<const backend::CharacterDrawItem> items() const = 0;
    /// The scene's camera at `seconds` (unless --camera fixes it).
    virtual scene::CameraPose orbitPose(double seconds) const = 0;

    /// Makes the scene's orbit a dolly to `endDistance` metres over
    /// `seconds` (--orbit-distance A:B).
    virtual void dollyOrbit(float endDistance, double seconds) = 0;

    /// The instanced crowd this population can be drawn as
    /// (Backend::drawCrowd), or null when it draws only through items().
    virtual InstancedCrowd* instancedCrowd() { return nullptr; }
    /// From now on update() fills instancedCrowd() instead of items() (the
    /// backend made the crowd), or items() again with `instanced` false (the
    /// backend that made it is being replaced).
    virtual void useInstancedCrowd(bool /*instanced*/) {}
    /// What casts shadows on the terrain: the feet (xyz) and height (w), in
    /// metres, of the characters standing in `region` (x, y: its min corner
    /// in world XZ, z: its side), the `limit` nearest its centre when there
    /// are more. By default the characters drawn this frame (items()); the
    /// crowd gives every agent, drawn instanced or not.
    virtual void shadowCasters(const glm::vec3& region, uint32_t limit, std::vector<glm::vec4>& out);
    /// The most instances instancedCrowd() will have in a frame.
    virtual uint32_t instanceCapacity() const { return 0; }
};

} // namespace tessera::runtime
