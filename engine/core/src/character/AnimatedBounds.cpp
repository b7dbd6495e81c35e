#include "tessera/character/AnimatedBounds.h"

#include "tessera/character/Pose.h"
#include "tessera/character/SkinnedVertex.h"

#include <algorithm>
#include <vector>

namespace tessera::character {

namespace {

void expandBySkinnedCage(const CageMesh& cage, const Pose& pose, std::vector<glm::mat4>& palette, scene::Aabb& box) {
    pose.palette(cage, palette);
    for (const CageVertex& vertex : cage.vertices) box.expand(skinVertex(vertex, palette).position);
}

} // namespace

scene::Aabb animatedBounds(const CharacterAsset& character, uint32_t samplesPerClip, float margin) {
    scene::Aabb box = scene::Aabb::empty();
    if (character.cage.vertices.empty()) return box;
    Pose pose(character.skeleton);
    std::vector<glm::mat4> palette;
    expandBySkinnedCage(character.cage, pose, palette, box);
    const uint32_t samples = std::max(samplesPerClip, 2u);
    for (const AnimationClip& clip : character.clips) {
        const float duration = clip.duration();
        for (uint32_t s = 0; s < samples; ++s) {
            pose.reset();
            pose.apply(clip, duration * static_cast<float>(s) / static_cast<float>(samples - 1), false);
            pose.computeGlobals();
            expandBySkinnedCage(character.cage, pose, palette, box);
        }
    }
    const glm::vec3 size = box.max - box.min;
    const float pad = margin * std::max({size.x, size.y, size.z});
    box.min -= glm::vec3(pad);
    box.max += glm::vec3(pad);
    return box;
}

} // namespace tessera::character
