#pragma once
/// @file CameraPose.h
/// A camera position and heading, and its text form.

#include <glm/glm.hpp>
#include <string>

namespace tessera::scene {

/// Where a camera is and where it looks. Angles in radians, with Camera's
/// conventions: yaw 0 looks toward -Z, positive yaw turns toward -X
/// (counter-clockwise seen from above); positive pitch looks up.
struct CameraPose {
    glm::vec3 position{0.0f};
    float yaw = 0.0f;
    float pitch = 0.0f;
};

/// Formats `pose` as "x,y,z,yaw,pitch": the position in metres, yaw and pitch
/// in degrees, each the shortest text that reads back to the same float,
/// independent of the locale. A host logs a pose in this form and reads it
/// back from its own settings (the command line's reader is
/// tessera/cli/CameraPoseText.h); it round-trips to within float rounding of
/// the degree/radian conversion.
std::string formatCameraPose(const CameraPose& pose);

} // namespace tessera::scene
