#pragma once
/// @file OverlayActions.h
/// What the window's controls ask for that cannot happen in the middle of a
/// UI frame: the controller applies them between frames.

#include <cstdint>
#include <optional>
#include <string>

namespace tessera::runtime {

struct OverlayActions {
    std::string switchBackend;      ///< non-empty: re-create the scene on this backend
    std::optional<uint32_t> agents; ///< reload the crowd scene with this many agents
    bool dropMeteor = false;        ///< a crater ahead of the camera
    bool screenshot = false;        ///< this frame to a PNG (without the overlay)
    bool capture = false;           ///< the next frame through RenderDoc
};

} // namespace tessera::runtime
