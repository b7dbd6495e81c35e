#pragma once
/// @file FrameInfo.h
/// Per-frame parameters the host hands to Backend::beginFrame.

#include "tessera/scene/ShadowCascade.h"

#include <cstdint>
#include <glm/glm.hpp>
#include <span>

namespace tessera::gpu {
class FrameContext; // the shared Vulkan layer's frame; opaque to the data model
}

namespace tessera::backend {

/// How the frame is shaded (docs/LOOKS.md). Plain is the shading from before
/// the looks (no sky, tone mapping or terrain shadows), kept so one run can
/// measure what the full look costs.
enum class Look : uint32_t {
    Plain = 0, ///< clear-colour background, distance fog, unencoded colour
    Full = 1,  ///< analytic sky, aerial-perspective fog, sun shadows, filmic tone mapping, sRGB encode
};

/// Where the full look shades the terrain (docs/LOOKS.md, "Deferred terrain
/// shading"): in its own fragments in the main pass, or once per pixel after
/// it, from the distance its fragments store (the terrain resolve: compute
/// on backends with compute, a fullscreen pass on the others).
enum class TerrainShading : uint32_t {
    Auto = 0,     ///< deferred where the resolve runs in compute on a GPU, else forward
    Forward = 1,  ///< every terrain fragment shades itself
    Deferred = 2, ///< the terrain resolve shades each terrain pixel once
};

/// How characters shadow the scene in the full look (docs/LOOKS.md,
/// "Characters' shadows on the terrain" and "Cascaded shadow maps").
enum class Shadows : uint32_t {
    Auto = 0,     ///< each backend's cheaper choice for the device (BackendCapabilities::cascadedShadows)
    Blob = 1,     ///< a soft ellipse per character on the terrain: the cheapest
    Cascaded = 2, ///< cascaded shadow maps of the characters: on the terrain and on each other
    None = 3,     ///< no character shadows: what the others cost is measured against it
};

struct FrameInfo {
    uint64_t frameIndex = 0;
    double timeSeconds = 0.0;
    glm::mat4 view{1.0f};
    glm::mat4 projection{1.0f};
    glm::mat4 viewProjection{1.0f};
    glm::vec3 cameraPosition{0.0f};
    glm::vec3 sunDirection{0.4f, 0.8f, 0.3f}; ///< towards the sun, normalised by the backend
    glm::vec4 clearColor{0.55f, 0.68f, 0.85f, 1.0f};
    uint32_t width = 0;
    uint32_t height = 0;
    bool wireframe = false;
    Look look = Look::Full;
    TerrainShading terrainShading = TerrainShading::Auto; ///< with the full look
    /// Characters' shadows on the terrain: the feet (xyz) and height (w) in
    /// metres of each character standing in `shadowRegion`, the square of
    /// ground the backend's shadow mask covers (x, y: its min corner in
    /// world XZ, z: its side; z = 0: no character shadows this frame).
    std::span<const glm::vec4> shadowCasters;
    glm::vec3 shadowRegion{0.0f};
    Shadows shadows = Shadows::Auto; ///< with the full look
    /// The cascades fitted to this frame's view and sun (scene::ShadowCascadeFit),
    /// nearest first; empty where the host asks for no cascaded shadows.
    std::span<const scene::ShadowCascade> shadowCascades;
    /// The command buffer, target and profiler of this frame; null on the null
    /// backend, which runs the frame logic with no GPU.
    gpu::FrameContext* gpu = nullptr;
};

} // namespace tessera::backend
