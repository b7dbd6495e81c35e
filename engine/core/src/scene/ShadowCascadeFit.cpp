#include "tessera/scene/ShadowCascadeFit.h"

#include "tessera/scene/CascadeSplits.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace tessera::scene {

namespace {

/// The smallest sphere around a frustum slice between view depths n and f,
/// where a depth-d cross-section's corners lie d * k off the axis: its
/// centre is on the axis (the slice is symmetric), at the depth where the
/// near and far corners are equally far, unless that is past the far plane
/// (a wide, thin slice), where the far rectangle's circle holds it all.
struct SliceSphere {
    float depth;
    float radius;
};

SliceSphere sliceSphere(float n, float f, float k) {
    const float k2 = k * k;
    const float depth = 0.5f * (n + f) * (1.0f + k2);
    if (depth >= f) return {f, f * k};
    return {depth, std::sqrt((f - depth) * (f - depth) + f * f * k2)};
}

} // namespace

ShadowCascadeFit::Settings ShadowCascadeFit::Settings::forDevice(lod::DeviceClass device) {
    Settings settings;
    if (device == lod::DeviceClass::Cpu) {
        // lavapipe (docs/LOOKS.md, "The cost and auto"): each receiver's tap
        // is a 2x2 comparison filtered in software, over every terrain and
        // creature pixel, and each cascade a depth pass whose culled casters
        // still run their vertex stage's first lines. One tap (2x2 texels
        // filtered, crisper than the GPU's 4x4, not noisier at these
        // sizes), two cascades split half uniformly (the near one to about
        // 29 m, texels under a decimetre; the far one's coarser, blob-like,
        // as blobs are there) and 100 m of shadow, a third beyond the blob
        // mask's reach: beyond it the creatures are ten pixels tall, cast
        // nothing and their receivers sample nothing (150 m cost lavapipe
        // about 5% more a frame for shadows of creatures that small).
        settings.cascadeCount = 2;
        settings.splitLambda = 0.5f;
        settings.shadowDistance = 100.0f;
        settings.pcfTaps = 1;
    }
    return settings;
}

ShadowCascadeFit::ShadowCascadeFit(const Settings& settings) : mSettings(settings) {
    assert(settings.cascadeCount >= 1 && settings.cascadeCount <= kMaxCascades && "ShadowCascadeFit: cascade count");
    assert(settings.shadowDistance > 0.0f && "ShadowCascadeFit: shadow distance must be positive");
    assert(settings.splitLambda >= 0.0f && settings.splitLambda <= 1.0f && "ShadowCascadeFit: lambda outside 0..1");
    assert(settings.resolution >= 16 && "ShadowCascadeFit: resolution too small");
    assert(settings.casterReach >= 0.0f && "ShadowCascadeFit: negative caster reach");
    assert(settings.pcfTaps >= 1 && settings.pcfTaps <= 3 && "ShadowCascadeFit: taps outside 1..3");
}

glm::mat4 ShadowCascadeFit::sunView(const glm::vec3& towardsSun) {
    const glm::vec3 sun = glm::normalize(towardsSun);
    // The up vector depends on the sun alone, never on the camera: a view
    // that turned with the camera would move every texel as it turned.
    const glm::vec3 up = std::abs(sun.y) < 0.99985f ? glm::vec3(0.0f, 1.0f, 0.0f) : glm::vec3(0.0f, 0.0f, -1.0f);
    return glm::lookAtRH(glm::vec3(0.0f), -sun, up);
}

std::vector<ShadowCascade> ShadowCascadeFit::fit(const Camera& camera, const glm::vec3& towardsSun) const {
    const float nearDistance = camera.nearPlane();
    const float farDistance = std::min(mSettings.shadowDistance, camera.farPlane());
    const std::vector<float> splits =
        practicalCascadeSplits(nearDistance, farDistance, mSettings.cascadeCount, mSettings.splitLambda);
    const float tanY = std::tan(0.5f * camera.verticalFov());
    const float k = tanY * std::sqrt(1.0f + camera.aspect() * camera.aspect());
    const glm::vec3 forward = camera.forward();
    const glm::mat4 view = sunView(towardsSun);

    std::vector<ShadowCascade> cascades(mSettings.cascadeCount);
    for (uint32_t i = 0; i < mSettings.cascadeCount; ++i) {
        ShadowCascade& c = cascades[i];
        c.nearDistance = splits[i];
        c.farDistance = splits[i + 1];
        const SliceSphere sphere = sliceSphere(c.nearDistance, c.farDistance, k);
        // Rounded up to 1/16 m so that float noise in the sphere (the camera's
        // lens is fixed, but its terms are recomputed every frame) never
        // changes the texel size by a hair and resamples the whole map.
        c.radius = std::ceil(sphere.radius * 16.0f) / 16.0f;
        c.center = camera.position() + forward * sphere.depth;
        c.texelSize = 2.0f * c.radius / float(mSettings.resolution);

        // Snap the centre to whole texels of the sun's view: as the camera
        // moves, the projection then slides by whole texels only.
        const glm::vec3 centerLs = glm::vec3(view * glm::vec4(c.center, 1.0f));
        const float x = std::round(centerLs.x / c.texelSize) * c.texelSize;
        const float y = std::round(centerLs.y / c.texelSize) * c.texelSize;
        // The sun's view looks down -Z: the sphere spans view z in
        // [centre - r, centre + r]; the casters' reach extends it towards
        // the sun (+Z), where the nearest depth (0) lies.
        const float zNear = -centerLs.z - c.radius - mSettings.casterReach;
        const float zFar = -centerLs.z + c.radius;
        c.depthRange = zFar - zNear;
        c.view = view;
        c.projection = glm::orthoRH_ZO(x - c.radius, x + c.radius, y - c.radius, y + c.radius, zNear, zFar);
        c.viewProjection = c.projection * c.view;
    }
    return cascades;
}

size_t ShadowCascadeFit::cascadeIndex(const std::vector<ShadowCascade>& cascades, float viewDepth) {
    for (size_t i = 0; i < cascades.size(); ++i) {
        if (viewDepth <= cascades[i].farDistance) return i;
    }
    return cascades.size();
}

} // namespace tessera::scene
