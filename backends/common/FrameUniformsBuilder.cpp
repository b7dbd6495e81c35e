#include "FrameUniformsBuilder.h"

namespace tessera::backends {

shader::FrameUniforms buildFrameUniforms(const backend::FrameInfo& frame) {
    shader::FrameUniforms u{};
    u.viewProjection = frame.viewProjection;
    u.view = frame.view;
    u.cameraPosition = glm::vec4(frame.cameraPosition, static_cast<float>(frame.timeSeconds));
    u.sunDirection = glm::vec4(glm::normalize(frame.sunDirection), 0.0f);
    // Fog fades to the clear colour, so the far edge of the terrain blends into the sky.
    u.fogColor = glm::vec4(glm::vec3(frame.clearColor), 0.00012f);
    const float w = static_cast<float>(frame.width ? frame.width : 1);
    const float h = static_cast<float>(frame.height ? frame.height : 1);
    u.viewport = glm::vec4(w, h, 1.0f / w, 1.0f / h);
    return u;
}

} // namespace tessera::backends
