#include "tessera/scene/ShadowCascadeUniforms.h"

#include <cassert>

namespace tessera::scene {

shader::ShadowCascadeUniforms buildShadowCascadeUniforms(std::span<const ShadowCascade> cascades,
                                                         uint32_t resolution, float normalOffsetTexels,
                                                         float depthBiasMetres) {
    assert(cascades.size() <= TS_SHADOW_MAX_CASCADES && "buildShadowCascadeUniforms: too many cascades");
    assert(resolution > 0 && "buildShadowCascadeUniforms: no map size");
    shader::ShadowCascadeUniforms u{};
    for (size_t i = 0; i < cascades.size(); ++i) {
        u.viewProjection[i] = cascades[i].viewProjection;
        u.farDistances[int(i)] = cascades[i].farDistance;
        u.texelSizes[int(i)] = cascades[i].texelSize;
        u.depthRanges[int(i)] = cascades[i].depthRange;
    }
    u.params = glm::vec4(float(cascades.size()), 1.0f / float(resolution), normalOffsetTexels, depthBiasMetres);
    return u;
}

} // namespace tessera::scene
