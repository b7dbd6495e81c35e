#include "world/ShadowCasters.h"

#include <algorithm>
#include <cmath>

namespace tessera::runtime {

glm::vec3 shadowRegionFor(const scene::Camera& camera) {
    glm::vec2 ahead(camera.forward().x, camera.forward().z);
    const float length = glm::length(ahead);
    // Looking straight down: centred on the camera.
    ahead = length > 1e-3f ? ahead / length : glm::vec2(0.0f);
    const glm::vec2 centre = glm::vec2(camera.position().x, camera.position().z) + ahead * (0.4f * kShadowRegionSide);
    return glm::vec3(centre - glm::vec2(0.5f * kShadowRegionSide), kShadowRegionSide);
}

void keepNearest(const glm::vec3& region, uint32_t limit, std::vector<glm::vec4>& casters) {
    if (casters.size() <= limit) return;
    const glm::vec2 centre(region.x + 0.5f * region.z, region.y + 0.5f * region.z);
    auto distance = [&centre](const glm::vec4& c) { return glm::length(glm::vec2(c.x, c.z) - centre); };
    std::nth_element(casters.begin(), casters.begin() + limit, casters.end(),
                     [&](const glm::vec4& a, const glm::vec4& b) { return distance(a) < distance(b); });
    casters.resize(limit);
}

} // namespace tessera::runtime
