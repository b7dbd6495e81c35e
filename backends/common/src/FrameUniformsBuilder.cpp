#include "common/FrameUniformsBuilder.h"

#include <cmath>

namespace tessera::backends {

namespace {
// The full look's light and atmosphere (docs/LOOKS.md), in linear units where
// a white surface facing the sun reflects kSunRadiance.
const glm::vec3 kSunRadiance{3.1f, 2.9f, 2.55f};
constexpr float kSunDiscRadians = 0.0093f; // ~0.53 degrees across, twice the real sun
constexpr float kExposure = 0.85f;
// Haze 0.16 per km at sea level, thinning by e every 500 m up.
constexpr float kFogDensity = 0.00016f;
constexpr float kFogFalloff = 1.0f / 500.0f;
constexpr float kFogReferenceHeight = 0.0f;
} // namespace

shader::FrameUniforms buildFrameUniforms(const backend::FrameInfo& frame, bool terrainDeferred) {
    shader::FrameUniforms u{};
    u.viewProjection = frame.viewProjection;
    u.view = frame.view;
    u.cameraPosition = glm::vec4(frame.cameraPosition, static_cast<float>(frame.timeSeconds));
    u.sunDirection = glm::vec4(glm::normalize(frame.sunDirection), 0.0f);
    const float w = static_cast<float>(frame.width ? frame.width : 1);
    const float h = static_cast<float>(frame.height ? frame.height : 1);
    u.viewport = glm::vec4(w, h, 1.0f / w, 1.0f / h);
    // The resolve picks the detail textures' mip from each pixel's footprint
    // (it has no derivatives in compute): the footprint of a pixel is its
    // distance times this.
    const float focal = std::abs(frame.projection[1][1]);
    const float pixelAngle = focal > 0.0f ? 2.0f / (h * focal) : 0.0f;
    const float sx = frame.projection[0][0] != 0.0f ? 1.0f / frame.projection[0][0] : 0.0f;
    const float sy = frame.projection[1][1] != 0.0f ? 1.0f / frame.projection[1][1] : 0.0f;
    u.terrainResolve = glm::vec4(terrainDeferred && frame.look == backend::Look::Full ? 1.0f : 0.0f, pixelAngle, sx, sy);
    u.sunColor = glm::vec4(kSunRadiance, std::cos(kSunDiscRadians * 0.5f));
    // The characters' shadows: only where the host gave casters (and then the
    // backend draws the mask before the terrain).
    const bool shadows = !frame.shadowCasters.empty() && frame.shadowRegion.z > 0.0f;
    u.characterShadow = shadows ? glm::vec4(frame.shadowRegion.x, frame.shadowRegion.y, 1.0f / frame.shadowRegion.z, 1.0f)
                                : glm::vec4(0.0f);
    if (frame.look == backend::Look::Full) {
        // The fog's colour is the sky's (sky_atmosphere.glsl). Its density
        // falls off with height; the shaders integrate it from the camera's.
        const float atCamera = kFogDensity * std::exp(-kFogFalloff * (frame.cameraPosition.y - kFogReferenceHeight));
        u.fogColor = glm::vec4(glm::vec3(frame.clearColor), kFogDensity);
        u.look = glm::vec4(float(TS_LOOK_FULL), kExposure, kFogFalloff, atCamera);
    } else {
        // Fog fades to the clear colour, so the far edge of the terrain blends into the sky.
        u.fogColor = glm::vec4(glm::vec3(frame.clearColor), 0.00012f);
        u.look = glm::vec4(float(TS_LOOK_PLAIN), 1.0f, 0.0f, 0.0f);
    }
    return u;
}

} // namespace tessera::backends
