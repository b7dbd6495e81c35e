#pragma once
/// @file CameraPose.h
/// A camera position and heading, and its command-line form.

#include "tessera/core/Result.h"

#include <glm/glm.hpp>
#include <string>
#include <string_view>

namespace tessera::scene {

/// Where a camera is and where it looks. Angles in radians, with Camera's
/// conventions: yaw 0 looks toward -Z, positive yaw turns toward -X
/// (counter-clockwise seen from above); positive pitch looks up.
struct CameraPose {
    glm::vec3 position{0.0f};
    float yaw = 0.0f;
    float pitch = 0.0f;
};

/// Parses the command-line form "x,y,z,yaw,pitch": position in metres, yaw and
/// pitch in DEGREES (returned in radians). Exactly five finite decimal numbers
/// separated by commas; spaces and tabs around each number are allowed.
/// Locale-independent (std::from_chars). On bad input the Error message says
/// what is wrong, e.g. `--camera expects x,y,z,yaw,pitch (5 numbers), got "1,2"`.
Result<CameraPose> parseCameraPose(std::string_view text);

/// Formats `pose` in the form parseCameraPose() reads (degrees), so a pose can
/// be logged and replayed with --camera. Round-trips to within float rounding
/// of the degree/radian conversion.
std::string formatCameraPose(const CameraPose& pose);

} // namespace tessera::scene
