#pragma once
/// @file CameraPath.h
/// A deterministic, seeded flythrough over terrain, for demos and benchmarks.

#include "tessera/scene/CameraPose.h"

#include <cstdint>
#include <functional>
#include <glm/glm.hpp>
#include <vector>

namespace tessera::scene {

/// Parameters of a CameraPath. The same settings and ground give the same path.
struct CameraPathSettings {
    /// Picks the control points (tessera::Random, so identical on every platform).
    uint32_t seed = 1;
    /// The world XZ rectangle to fly over; the loop keeps ~10% away from its edges.
    glm::vec2 regionMin{-1000.0f};
    glm::vec2 regionMax{1000.0f};
    /// Target height above the ground, metres. The path is never lower than
    /// ground + clearance at its sample stations (every ~2 m), and so in
    /// practice never below ground + clearance / 2 anywhere.
    float clearance = 40.0f;
    /// Flight speed, metres per second, held steady along the path.
    float speed = 60.0f;
    /// Number of control points around the loop; values below 4 are raised to 4.
    int controlPoints = 8;
};

/// A closed loop over a region, flown at constant speed, looking ahead and
/// somewhat down so the terrain fills most of the view.
///
/// Construction (the only time the ground is sampled):
/// 1. Control points are placed around an ellipse inscribed in the region less
///    a 10% margin, with seeded jitter in angle and radius.
/// 2. They are joined by a closed centripetal Catmull-Rom spline in XZ
///    (centripetal: no cusps or self-loops however uneven the spacing), and an
///    arc-length table maps distance along the loop to spline parameter.
/// 3. The ground is sampled at stations every ~2 m along the loop. The altitude
///    profile is a sliding maximum of the ground (radius max(3 * clearance,
///    2 s of flight)) plus clearance, then smoothed by two box filters whose
///    combined radius equals the maximum's. A weighted average of values that
///    each exceed ground + clearance at a station exceeds it too, so smoothing
///    never pulls the path into a hill; between stations the ground can rise
///    only as far as its slope allows over ~1 m.
///
/// The ground is sampled per station rather than only at the control points
/// because a ridge between two control points would otherwise cut the path.
///
/// sample() is a pure function of its argument: the same settings, ground and
/// time give bit-identical poses, and calls may run concurrently.
class CameraPath {
public:
    /// Ground height in metres at world (x, z). An empty function means flat
    /// ground at height 0. Called only during construction, never stored.
    using GroundHeight = std::function<float(float x, float z)>;

    /// Builds the path. Asserts regionMin < regionMax, speed > 0, clearance >= 0.
    CameraPath(const CameraPathSettings& settings, const GroundHeight& groundHeight);

    /// Pose at `timeSeconds`, which wraps with period() (negative times too).
    /// Yaw follows the horizontal tangent; pitch is the climb angle (limited to
    /// +-20 degrees) minus a 20 degree look-down.
    CameraPose sample(double timeSeconds) const;

    /// Seconds to fly the loop once.
    double period() const { return mLength / mSpeed; }

    /// Length of the loop in XZ, metres.
    double length() const { return mLength; }

private:
    glm::dvec2 evaluateSpline(double u) const;
    double parameterAt(double distance) const;
    glm::dvec2 positionAt(double distance) const;
    double altitudeAt(double distance) const;
    double wrapDistance(double distance) const;
    void buildAltitudeProfile(const CameraPathSettings& settings, const GroundHeight& ground);

    std::vector<glm::dvec2> mControlPoints;
    /// Arc length from the start to spline parameter u = i / kSamplesPerSegment.
    std::vector<double> mArcLength;
    /// Altitude at stations spaced mStationSpacing apart, starting at distance 0.
    std::vector<double> mAltitude;
    double mStationSpacing = 1.0;
    double mLength = 0.0;
    double mSpeed = 1.0;
};

} // namespace tessera::scene
