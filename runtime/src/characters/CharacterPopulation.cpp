#include "tessera/runtime/CharacterPopulation.h"

#include "world/ShadowCasters.h"

#include <algorithm>

namespace tessera::runtime {

void CharacterPopulation::shadowCasters(const glm::vec3& region, uint32_t limit, std::vector<glm::vec4>& out) {
    out.clear();
    // Drawn as an instanced crowd: its instances are the characters.
    if (InstancedCrowd* crowd = instancedCrowd(); crowd && items().empty()) {
        // As tall as the asset's box (animated bounds).
        const CharacterAssets& all = assets();
        std::vector<float> heights(all.size());
        for (size_t i = 0; i < all.size(); ++i) heights[i] = all[i].box.max.y - all[i].box.min.y;
        crowd->shadowCasters(heights, region, out);
        keepNearest(region, limit, out);
        return;
    }
    const CharacterAssets& all = assets();
    for (const backend::CharacterDrawItem& item : items()) {
        if (item.fadingOut) continue; // the same character's other tier casts it
        // The asset's box in the world gives where the feet are and how tall
        // the character stands, whatever its units and orientation.
        const scene::Aabb* box = nullptr;
        for (size_t i = 0; i < all.size(); ++i)
            if (all.handle(i).id == item.character.id) box = &all[i].box;
        if (!box) continue;
        glm::vec3 lo(1e30f), hi(-1e30f);
        for (int c = 0; c < 8; ++c) {
            const glm::vec3 corner((c & 1) ? box->max.x : box->min.x, (c & 2) ? box->max.y : box->min.y,
                                   (c & 4) ? box->max.z : box->min.z);
            const glm::vec3 world = glm::vec3(item.world * glm::vec4(corner, 1.0f));
            lo = glm::min(lo, world);
            hi = glm::max(hi, world);
        }
        const glm::vec3 feet(0.5f * (lo.x + hi.x), lo.y, 0.5f * (lo.z + hi.z));
        if (insideRegion(region, feet)) out.emplace_back(feet, hi.y - lo.y);
    }
    keepNearest(region, limit, out);
}

} // namespace tessera::runtime
