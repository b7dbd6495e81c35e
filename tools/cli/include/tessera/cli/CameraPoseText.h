#pragma once
/// @file CameraPoseText.h
/// A camera pose as a command line writes it, "x,y,z,yaw,pitch": the demo's
/// --camera and the report's, read by the one list reader (NumberList.h).
/// The engine takes the numbers (scene::CameraPose); scene::formatCameraPose
/// writes a pose in this form, so a logged pose can be given back.

#include "tessera/core/Result.h"
#include "tessera/scene/CameraPose.h"

#include <string_view>

namespace tessera::cli {

/// Parses "x,y,z,yaw,pitch": position in metres, yaw and pitch in DEGREES
/// (returned in radians). Exactly five finite numbers separated by commas,
/// by NumberList's rules (spaces and tabs around each number, one leading
/// '+'). An Error names `flag` and what is wrong, e.g.
/// `--camera expects x,y,z,yaw,pitch (5 numbers), got "1,2"` or
/// `--camera: y = "abc" is not a number`.
Result<scene::CameraPose> parseCameraPose(std::string_view text, std::string_view flag = "--camera");

} // namespace tessera::cli
