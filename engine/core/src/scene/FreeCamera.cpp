#include "tessera/scene/FreeCamera.h"

#include <algorithm>
#include <cmath>

namespace tessera::scene {

FreeCamera::FreeCamera(const CameraPose& pose, float speed, float sensitivity)
    : mSpeed(speed), mSensitivity(sensitivity) {
    setPose(pose);
}

void FreeCamera::setPose(const CameraPose& pose) {
    mPose = pose;
    mPose.pitch = std::clamp(pose.pitch, -kMaxPitch, kMaxPitch);
}

void FreeCamera::update(const FreeCameraInput& input, float seconds) {
    // Mouse to the right turns right: yaw is a rotation about +Y, which
    // turns the view towards -X as it grows (Camera::forward).
    mPose.yaw -= input.lookX * mSensitivity;
    mPose.pitch = std::clamp(mPose.pitch - input.lookY * mSensitivity, -kMaxPitch, kMaxPitch);
    mPose.yaw = std::remainder(mPose.yaw, 2.0f * 3.14159265358979f);

    // The same basis as Camera::forward() and Camera::right().
    const float cosPitch = std::cos(mPose.pitch);
    const glm::vec3 forward(-std::sin(mPose.yaw) * cosPitch, std::sin(mPose.pitch), -std::cos(mPose.yaw) * cosPitch);
    const glm::vec3 right(std::cos(mPose.yaw), 0.0f, -std::sin(mPose.yaw));
    glm::vec3 move = forward * input.forward + right * input.right + glm::vec3(0.0f, input.up, 0.0f);
    const float length = glm::length(move);
    if (length > 1.0f) move /= length; // diagonals are no faster
    const float speed = mSpeed * (input.fast ? kFastFactor : 1.0f);
    mPose.position += move * speed * seconds;
}

} // namespace tessera::scene
