#pragma once
/// @file Camera.h
/// A yaw/pitch perspective camera producing Vulkan-ready matrices.

#include "tessera/scene/CameraPose.h"
#include "tessera/scene/Frustum.h"

#include <glm/glm.hpp>

namespace tessera::scene {

/// A first-person camera: a position, a heading (yaw, pitch; no roll) and a
/// perspective lens. World space is right-handed with +Y up.
///
/// Angles are radians. Yaw 0 looks toward -Z; positive yaw turns toward -X
/// (counter-clockwise seen from above). Positive pitch looks up; pitch is not
/// clamped, and the view stays well defined even straight up or down because
/// it is built from rotations rather than lookAt().
///
/// projection() maps depth to 0..1 (Vulkan's convention, glm::perspectiveRH_ZO) and flips Y,
/// because Vulkan's viewport has +Y pointing down: with the flip, world +Y is
/// up on screen without a negative-height viewport. Consequently a point above
/// the view centre has NEGATIVE NDC y.
class Camera {
public:
    static constexpr float kDefaultVerticalFov = 1.04719755f; // 60 degrees
    static constexpr float kDefaultNearPlane = 0.5f;
    static constexpr float kDefaultFarPlane = 20000.0f;
    static constexpr float kDefaultAspect = 16.0f / 9.0f;

    void setPosition(const glm::vec3& position) { mPosition = position; }
    const glm::vec3& position() const { return mPosition; }

    void setYaw(float radians) { mYaw = radians; }
    float yaw() const { return mYaw; }

    void setPitch(float radians) { mPitch = radians; }
    float pitch() const { return mPitch; }

    /// Sets position, yaw and pitch at once.
    void setPose(const CameraPose& pose);
    /// Position, yaw and pitch as a pose.
    CameraPose pose() const { return CameraPose{mPosition, mYaw, mPitch}; }

    /// Vertical field of view in radians; asserts 0 < fov < pi.
    void setVerticalFov(float radians);
    float verticalFov() const { return mVerticalFov; }

    /// Near and far clip distances; asserts 0 < near < far.
    void setClipPlanes(float nearPlane, float farPlane);
    float nearPlane() const { return mNearPlane; }
    float farPlane() const { return mFarPlane; }

    /// Viewport width / height; asserts > 0.
    void setAspect(float aspect);
    float aspect() const { return mAspect; }

    /// Unit view direction.
    glm::vec3 forward() const;
    /// Unit vector to the right of the view, always horizontal (no roll).
    glm::vec3 right() const;

    /// World-to-view matrix (view space looks down -Z, +Y up, +X right).
    glm::mat4 view() const;
    /// View-to-clip matrix: perspective, depth 0..1, Y flipped for Vulkan.
    glm::mat4 projection() const;
    /// projection() * view().
    glm::mat4 viewProjection() const;
    /// The world-space frustum of viewProjection().
    Frustum frustum() const;

private:
    glm::vec3 mPosition{0.0f};
    float mYaw = 0.0f;
    float mPitch = 0.0f;
    float mVerticalFov = kDefaultVerticalFov;
    float mNearPlane = kDefaultNearPlane;
    float mFarPlane = kDefaultFarPlane;
    float mAspect = kDefaultAspect;
};

} // namespace tessera::scene
