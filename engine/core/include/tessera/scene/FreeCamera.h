#pragma once
/// @file FreeCamera.h
/// A first-person fly camera driven by movement keys and mouse motion (the
/// demo window's WASD + mouse), as plain state and arithmetic: the host
/// turns its input into a FreeCameraInput each frame.

#include "tessera/scene/CameraPose.h"

#include <glm/glm.hpp>

namespace tessera::scene {

/// One frame's input. Movement axes are -1, 0 or +1 (or anything between,
/// for a gamepad); look deltas are in pixels of mouse travel.
struct FreeCameraInput {
    float forward = 0.0f; ///< +1: W, -1: S
    float right = 0.0f;   ///< +1: D, -1: A
    float up = 0.0f;      ///< +1: E, -1: Q (world up, whatever the pitch)
    float lookX = 0.0f;   ///< mouse travel to the right, pixels
    float lookY = 0.0f;   ///< mouse travel downwards, pixels
    bool fast = false;    ///< Shift: kFastFactor times the speed
};

class FreeCamera {
public:
    /// Pitch stays inside +-kMaxPitch so the view never flips over the pole.
    static constexpr float kMaxPitch = 1.5f;
    static constexpr float kFastFactor = 5.0f;

    /// Starts at `pose`; `speed` in metres per second, `sensitivity` in
    /// radians per pixel of mouse travel.
    explicit FreeCamera(const CameraPose& pose = {}, float speed = 40.0f, float sensitivity = 0.003f);

    /// Moves and turns for `seconds` of `input`: yaw and pitch first, then
    /// movement along the new view (forward follows the pitch, as flying).
    void update(const FreeCameraInput& input, float seconds);

    const CameraPose& pose() const { return mPose; }
    void setPose(const CameraPose& pose);
    float speed() const { return mSpeed; }
    void setSpeed(float metresPerSecond) { mSpeed = metresPerSecond; }

private:
    CameraPose mPose;
    float mSpeed;
    float mSensitivity;
};

} // namespace tessera::scene
