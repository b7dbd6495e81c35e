#pragma once
/// @file ShadowCascade.h
/// One cascade of a cascaded shadow map: the slice of the view it covers and
/// the sun's orthographic projection that covers it.

#include <glm/glm.hpp>

namespace tessera::scene {

/// A slice of the view frustum between two distances along the view axis
/// and the sun's view and orthographic projection fitted to it
/// (ShadowCascadeFit). Matrices follow Vulkan's clip space like Camera's:
/// depth 0..1, 0 nearest the sun. There is no Y flip: the shadow map is
/// rendered and sampled with the same convention (texel row 0 at clip y =
/// -1), so a point's texture coordinate is `clip.xy * 0.5 + 0.5`.
struct ShadowCascade {
    float nearDistance = 0.0f; ///< where the slice begins, metres along the view axis
    float farDistance = 0.0f;  ///< where it ends; a receiver at view depth d uses the first cascade with d <= farDistance
    glm::vec3 center{0.0f};    ///< centre of the slice's bounding sphere, world space
    float radius = 0.0f;       ///< that sphere's radius (metres), half the map's side
    float texelSize = 0.0f;    ///< metres one shadow-map texel spans: 2 * radius / resolution
    float depthRange = 0.0f;   ///< metres between the projection's depth 0 and depth 1 (for the depth bias)
    glm::mat4 view{1.0f};           ///< world to the sun's view: looks along -sunDirection, origin at world 0
    glm::mat4 projection{1.0f};     ///< orthographic, depth 0..1
    glm::mat4 viewProjection{1.0f}; ///< projection * view
};

} // namespace tessera::scene
