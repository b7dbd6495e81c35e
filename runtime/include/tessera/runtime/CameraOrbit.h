#pragma once
/// @file CameraOrbit.h
/// A camera circling a spot on the ground and looking at it: the characters
/// scene's and the crowd scene's view.

#include "tessera/scene/CameraPose.h"
#include "tessera/terrain/Terrain.h"

#include <glm/glm.hpp>

namespace tessera::runtime {

struct CameraOrbit {
    glm::vec3 site{0.0f};    ///< the spot circled and looked at (its height as the scene began)
    float distance = 5.0f;   ///< metres from the site, horizontally
    float height = 1.6f;     ///< metres above the site
    float lookHeight = 0.6f; ///< the camera aims this high above the site
    float clearance = 1.0f;  ///< metres above the ground under the camera, at least
    /// A dolly: over the first `dollySeconds` the distance goes from
    /// `distance` to `endDistance` (and the height with it, keeping the
    /// view's angle); 0 seconds: no dolly.
    float endDistance = 0.0f;
    double dollySeconds = 0.0;

    /// Radians per second around the site.
    static constexpr float kSpeed = 0.15f;
    /// The orbit starts on the sun's side (the azimuth of FrameInfo's default
    /// sun, atan2(0.4, 0.3)), so the first frames show lit faces.
    static constexpr float kStart = 0.93f;

    /// The pose at `seconds`. The site keeps its height when a crater lowers
    /// the ground there, so the camera does not sink into the crowd; it
    /// rises over ground that rises under it.
    scene::CameraPose pose(const terrain::Terrain& terrain, double seconds) const;
};

} // namespace tessera::runtime
