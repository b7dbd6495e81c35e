#include "tessera/scene/Camera.h"

#include <cassert>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace tessera::scene {

void Camera::setPose(const CameraPose& pose) {
    mPosition = pose.position;
    mYaw = pose.yaw;
    mPitch = pose.pitch;
}

void Camera::setVerticalFov(float radians) {
    assert(radians > 0.0f && radians < glm::pi<float>() && "Camera: field of view out of range");
    mVerticalFov = radians;
}

void Camera::setClipPlanes(float nearPlane, float farPlane) {
    assert(nearPlane > 0.0f && nearPlane < farPlane && "Camera: need 0 < near < far");
    mNearPlane = nearPlane;
    mFarPlane = farPlane;
}

void Camera::setAspect(float aspect) {
    assert(aspect > 0.0f && "Camera: aspect must be positive");
    mAspect = aspect;
}

glm::vec3 Camera::forward() const {
    // The camera's rotation is Ry(yaw) * Rx(pitch) applied to -Z.
    const float cosPitch = std::cos(mPitch);
    return glm::vec3(-std::sin(mYaw) * cosPitch, std::sin(mPitch), -std::cos(mYaw) * cosPitch);
}

glm::vec3 Camera::right() const {
    // Ry(yaw) applied to +X.
    return glm::vec3(std::cos(mYaw), 0.0f, -std::sin(mYaw));
}

glm::mat4 Camera::view() const {
    // The inverse of the camera's world transform T * Ry(yaw) * Rx(pitch).
    // Built from rotations rather than lookAt() so that looking straight up or
    // down is not a degenerate case.
    glm::mat4 m = glm::rotate(glm::mat4(1.0f), -mPitch, glm::vec3(1.0f, 0.0f, 0.0f));
    m = glm::rotate(m, -mYaw, glm::vec3(0.0f, 1.0f, 0.0f));
    return glm::translate(m, -mPosition);
}

glm::mat4 Camera::projection() const {
    // Vulkan's depth 0..1 by name (the _ZO variant), not by a GLM_FORCE_*
    // definition: that would be a compile definition every game linking
    // Tessera inherits, silently changing its own glm::perspective.
    glm::mat4 p = glm::perspectiveRH_ZO(mVerticalFov, mAspect, mNearPlane, mFarPlane);
    p[1][1] *= -1.0f;
    return p;
}

glm::mat4 Camera::viewProjection() const { return projection() * view(); }

Frustum Camera::frustum() const { return Frustum::fromViewProjection(viewProjection()); }

} // namespace tessera::scene
