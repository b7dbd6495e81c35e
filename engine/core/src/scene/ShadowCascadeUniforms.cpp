#include "tessera/scene/ShadowCascadeUniforms.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace tessera::scene {

shader::ShadowCascadeUniforms buildShadowCascadeUniforms(std::span<const ShadowCascade> cascades,
                                                         uint32_t resolution, uint32_t pcfTaps,
                                                         float normalOffsetTexels, float depthBiasMetres) {
    assert(cascades.size() <= TS_SHADOW_MAX_CASCADES && "buildShadowCascadeUniforms: too many cascades");
    assert(resolution > 0 && "buildShadowCascadeUniforms: no map size");
    assert(pcfTaps >= 1 && pcfTaps <= 3 && "buildShadowCascadeUniforms: taps outside 1..3");
    shader::ShadowCascadeUniforms u{};
    for (size_t i = 0; i < cascades.size(); ++i) {
        u.viewProjection[i] = cascades[i].viewProjection;
        u.farDistances[int(i)] = cascades[i].farDistance;
        u.texelSizes[int(i)] = cascades[i].texelSize;
        u.depthRanges[int(i)] = cascades[i].depthRange;
    }
    u.params = glm::vec4(float(cascades.size()), 1.0f / float(resolution), normalOffsetTexels, depthBiasMetres);
    u.pcf = glm::vec4(float(pcfTaps), 0.0f, 0.0f, 0.0f);
    return u;
}

shader::ShadowCasterPush buildShadowCasterPush(std::span<const ShadowCascade> cascades, size_t index,
                                               const glm::vec3& towardsSun) {
    assert(index < cascades.size() && "buildShadowCasterPush: no such cascade");
    const ShadowCascade& cascade = cascades[index];
    // A shadow reaches from the centre one radius to the feet plus the
    // length a body two radii tall casts, its height over the tangent of the
    // sun's elevation, and a radius more covers the receivers' filter and
    // offsets. The elevation is taken as at least --sun's lowest, 1 degree
    // (57 heights: the whole of most views' slices).
    const glm::vec3 sun = glm::normalize(towardsSun);
    const float sine = std::max(sun.y, std::sin(glm::radians(1.0f)));
    const float cotangent = std::sqrt(std::max(1.0f - sine * sine, 0.0f)) / sine;
    shader::ShadowCasterPush push{};
    push.viewProjection = cascade.viewProjection;
    // The first cascade also takes the casters nearer than the near plane;
    // a receiver beyond the last reads no cascade, so nothing beyond it casts.
    const float nearest = index == 0 ? -1e30f : cascade.nearDistance;
    push.cull = glm::vec4(nearest, cascade.farDistance, 1.0f / cascade.radius, 2.0f + 2.0f * cotangent);
    return push;
}

} // namespace tessera::scene
