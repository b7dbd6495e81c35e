#pragma once
/// @file ShadowCascadeFit.h
/// Fits a cascaded shadow map's cascades to a camera and the sun, stably.

#include "tessera/lod/LodPolicy.h"
#include "tessera/scene/Camera.h"
#include "tessera/scene/ShadowCascade.h"

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace tessera::scene {

/// Cascades fitted to a view (the Froblins' cascaded shadow maps; docs/LOOKS.md,
/// "Cascaded shadow maps"). The view from the camera's near plane out to
/// `Settings::shadowDistance` is cut by practicalCascadeSplits; each slice is
/// covered by one square orthographic projection from the sun.
///
/// The fit is stable, so shadow edges do not crawl or shimmer as the camera
/// moves and turns (Valient, "Stable Rendering of Cascaded Shadow Maps",
/// ShaderX6, 2008):
/// - each cascade covers the bounding sphere of its slice rather than the
///   slice's box in the sun's space, so its size, and with it the size of a
///   texel, does not change as the camera turns;
/// - the sun's view depends on the sun alone (origin at world 0, an up
///   vector chosen from the sun), and the projection's centre is snapped to
///   whole texels of that view, so as the camera moves the map's texels stay
///   on the same world positions and only whole texels enter and leave.
///
/// The depth range reaches `Settings::casterReach` metres beyond the sphere
/// towards the sun, so casters outside a slice still shadow it. Pure CPU,
/// no Vulkan: the backends upload the result (tests/unit/scene_shadow_cascade_test.cpp).
class ShadowCascadeFit {
public:
    /// The most cascades a fit makes (the shaders' uniform arrays hold this many).
    static constexpr uint32_t kMaxCascades = 4;

    struct Settings {
        uint32_t cascadeCount = 4;    ///< 1..kMaxCascades
        float shadowDistance = 300.0f; ///< metres along the view axis the cascades cover (clamped to the far plane)
        float splitLambda = 0.8f;     ///< practicalCascadeSplits' blend: 1 logarithmic, 0 uniform
        uint32_t resolution = 1024;   ///< texels on a side of each cascade's map
        float casterReach = 150.0f;   ///< metres towards the sun beyond a slice where casters are still drawn
        uint32_t pcfTaps = 3;         ///< receivers' bilinear comparison taps on a side (1 to 3; shadow_cascades.glsl)

        /// The defaults for `device` (docs/LOOKS.md, "The cost and auto"): on
        /// a CPU rasterizer two cascades over 150 m and one tap, which keep
        /// the full look with cascaded shadows near the look with blobs.
        static Settings forDevice(lod::DeviceClass device);
    };

    ShadowCascadeFit() = default;
    /// Asserts the settings are in range.
    explicit ShadowCascadeFit(const Settings& settings);

    const Settings& settings() const { return mSettings; }

    /// The cascades for `camera` and the unit direction `towardsSun` (any
    /// length; normalised here), nearest first, `cascadeCount` of them.
    std::vector<ShadowCascade> fit(const Camera& camera, const glm::vec3& towardsSun) const;

    /// The sun's view (looking along -towardsSun from world 0) every cascade
    /// of that sun shares; its up vector is world +Y turned into the view
    /// plane, or -Z when the sun is within a degree of the zenith.
    static glm::mat4 sunView(const glm::vec3& towardsSun);

    /// The index of the cascade a receiver at view depth `viewDepth` (metres
    /// along the view axis) reads, or cascades.size() beyond the last: the
    /// CPU twin of the shaders' selection.
    static size_t cascadeIndex(const std::vector<ShadowCascade>& cascades, float viewDepth);

private:
    Settings mSettings;
};

} // namespace tessera::scene
