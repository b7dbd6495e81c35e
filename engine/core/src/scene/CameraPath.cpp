#include "tessera/scene/CameraPath.h"

#include "tessera/core/Random.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <deque>

namespace tessera::scene {
namespace {

constexpr int kSamplesPerSegment = 64;      // Arc-length table resolution.
constexpr double kStationSpacing = 2.0;     // Target metres between ground samples.
constexpr size_t kMinStations = 256;
constexpr size_t kMaxStations = 32768;      // Bounds construction cost on huge regions.
constexpr double kMargin = 0.1;             // Fraction of the region kept free at each edge.
constexpr double kLookDown = 0.349065850398865915;  // 20 degrees.
constexpr double kMaxClimbPitch = 0.349065850398865915;  // 20 degrees.
constexpr double kPi = 3.14159265358979323846;

/// Knot spacing of the centripetal parameterisation: sqrt of the chord length.
double knotInterval(const glm::dvec2& a, const glm::dvec2& b) {
    // Floor keeps coincident points from dividing by zero.
    return std::max(std::sqrt(glm::length(b - a)), 1e-6);
}

/// Barry-Goldman pyramid evaluation of a centripetal Catmull-Rom segment
/// between p1 and p2 at local parameter t in [0, 1].
glm::dvec2 catmullRom(const glm::dvec2& p0, const glm::dvec2& p1, const glm::dvec2& p2,
                      const glm::dvec2& p3, double t) {
    const double t0 = 0.0;
    const double t1 = t0 + knotInterval(p0, p1);
    const double t2 = t1 + knotInterval(p1, p2);
    const double t3 = t2 + knotInterval(p2, p3);
    const double k = t1 + (t2 - t1) * t;
    const glm::dvec2 a1 = ((t1 - k) * p0 + (k - t0) * p1) / (t1 - t0);
    const glm::dvec2 a2 = ((t2 - k) * p1 + (k - t1) * p2) / (t2 - t1);
    const glm::dvec2 a3 = ((t3 - k) * p2 + (k - t2) * p3) / (t3 - t2);
    const glm::dvec2 b1 = ((t2 - k) * a1 + (k - t0) * a2) / (t2 - t0);
    const glm::dvec2 b2 = ((t3 - k) * a2 + (k - t1) * a3) / (t3 - t1);
    return ((t2 - k) * b1 + (k - t1) * b2) / (t2 - t1);
}

/// Circular sliding maximum of radius r (window 2r + 1), O(n) with a
/// monotonic deque. Requires 2r + 1 <= n.
std::vector<double> slidingMax(const std::vector<double>& v, size_t r) {
    const size_t n = v.size();
    std::vector<double> out(n);
    std::deque<size_t> window; // Positions in the unrolled sequence, values decreasing.
    // Unrolled position p stands for v[(p + n - r) % n], so out[k] is the max
    // over unrolled positions k .. k + 2r.
    auto at = [&](size_t p) { return v[(p + n - r) % n]; };
    for (size_t p = 0; p < n + 2 * r; ++p) {
        while (!window.empty() && at(window.back()) <= at(p)) window.pop_back();
        window.push_back(p);
        if (p < 2 * r) continue;
        const size_t k = p - 2 * r;
        if (window.front() < k) window.pop_front();
        out[k] = at(window.front());
    }
    return out;
}

/// Circular box filter of radius r (window 2r + 1). Requires 2r + 1 <= n.
std::vector<double> boxFilter(const std::vector<double>& v, size_t r) {
    const size_t n = v.size();
    std::vector<double> out(n);
    double sum = 0.0;
    for (size_t i = 0; i <= 2 * r; ++i) sum += v[(i + n - r) % n];
    for (size_t k = 0; k < n; ++k) {
        out[k] = sum / static_cast<double>(2 * r + 1);
        sum += v[(k + r + 1) % n] - v[(k + n - r) % n];
    }
    return out;
}

} // namespace

CameraPath::CameraPath(const CameraPathSettings& settings, const GroundHeight& groundHeight) {
    assert(glm::all(glm::lessThan(settings.regionMin, settings.regionMax)) &&
           "CameraPath: empty region");
    assert(settings.speed > 0.0f && "CameraPath: speed must be positive");
    assert(settings.clearance >= 0.0f && "CameraPath: negative clearance");
    mSpeed = settings.speed;

    // Control points on a seeded wobbly ellipse inside the region less the
    // margin. The radius never exceeds the ellipse, which leaves the whole
    // margin for the spline's overshoot between points.
    const int count = std::max(settings.controlPoints, 4);
    const glm::dvec2 lo(settings.regionMin), hi(settings.regionMax);
    const glm::dvec2 center = (lo + hi) * 0.5;
    const glm::dvec2 radius = (hi - lo) * (0.5 - kMargin);
    Random rng(settings.seed);
    // The wobble is three low harmonics rather than independent per-point
    // noise: with many control points, independent radii zigzag and the camera
    // would whip round at hundreds of degrees per second. Scale stays in
    // [0.55, 1].
    double amplitude[3], harmonicPhase[3];
    for (int k = 0; k < 3; ++k) {
        amplitude[k] = rng.range(0.0f, 0.075f);
        harmonicPhase[k] = rng.nextFloat() * 2.0 * kPi;
    }
    const double step = 2.0 * kPi / count;
    const double phase = rng.nextFloat() * 2.0 * kPi;
    for (int i = 0; i < count; ++i) {
        // Jitter below half a step keeps the points in angular order, so the
        // loop never crosses itself.
        const double angle = phase + step * (static_cast<double>(i) + rng.range(-0.3f, 0.3f));
        double scale = 0.775;
        for (int k = 0; k < 3; ++k) {
            scale += amplitude[k] * std::cos((k + 1) * angle + harmonicPhase[k]);
        }
        const glm::dvec2 direction(std::cos(angle), std::sin(angle));
        mControlPoints.push_back(center + radius * scale * direction);
    }

    // Arc-length table by summing chords of the finely sampled spline.
    const size_t tableSize = static_cast<size_t>(count) * kSamplesPerSegment;
    mArcLength.resize(tableSize + 1);
    mArcLength[0] = 0.0;
    glm::dvec2 previous = evaluateSpline(0.0);
    for (size_t i = 1; i <= tableSize; ++i) {
        const glm::dvec2 p = evaluateSpline(static_cast<double>(i) / kSamplesPerSegment);
        mArcLength[i] = mArcLength[i - 1] + glm::length(p - previous);
        previous = p;
    }
    mLength = mArcLength.back();

    buildAltitudeProfile(settings, groundHeight);
}

void CameraPath::buildAltitudeProfile(const CameraPathSettings& settings,
                                      const GroundHeight& ground) {
    const size_t stations = std::clamp(static_cast<size_t>(std::ceil(mLength / kStationSpacing)),
                                       kMinStations, kMaxStations);
    mStationSpacing = mLength / static_cast<double>(stations);
    std::vector<double> groundAt(stations, 0.0);
    if (ground) {
        for (size_t k = 0; k < stations; ++k) {
            const glm::dvec2 p = positionAt(static_cast<double>(k) * mStationSpacing);
            groundAt[k] = ground(static_cast<float>(p.x), static_cast<float>(p.y));
            assert(std::isfinite(groundAt[k]) && "CameraPath: ground height is not finite");
        }
    }

    // The radius sets how much the path smooths the terrain: wide enough that
    // the camera glides over bumps instead of tracing them, scaled with speed
    // so the climb rate stays comparable.
    const double radiusMetres = std::max(3.0 * settings.clearance, 2.0 * settings.speed);
    const size_t radius = std::min(static_cast<size_t>(std::ceil(radiusMetres / mStationSpacing)),
                                   (stations - 1) / 2);
    std::vector<double> profile = slidingMax(groundAt, radius);
    for (double& h : profile) h += settings.clearance;
    // Two boxes of radius r1 + r2 = radius: see the class comment for why the
    // result stays above ground + clearance at every station.
    const size_t first = radius / 2;
    profile = boxFilter(profile, first);
    profile = boxFilter(profile, radius - first);
    mAltitude = std::move(profile);
}

glm::dvec2 CameraPath::evaluateSpline(double u) const {
    const size_t n = mControlPoints.size();
    const double segment = std::floor(u);
    const double t = u - segment;
    const size_t i = static_cast<size_t>(segment) % n;
    return catmullRom(mControlPoints[(i + n - 1) % n], mControlPoints[i],
                      mControlPoints[(i + 1) % n], mControlPoints[(i + 2) % n], t);
}

double CameraPath::parameterAt(double distance) const {
    // First table entry beyond `distance`; lerp within the chord before it.
    auto it = std::upper_bound(mArcLength.begin(), mArcLength.end(), distance);
    if (it == mArcLength.end()) {
        return static_cast<double>(mArcLength.size() - 1) / kSamplesPerSegment;
    }
    const size_t j = static_cast<size_t>(it - mArcLength.begin());
    const double s0 = mArcLength[j - 1], s1 = mArcLength[j];
    const double f = s1 > s0 ? (distance - s0) / (s1 - s0) : 0.0;
    return (static_cast<double>(j - 1) + f) / kSamplesPerSegment;
}

double CameraPath::wrapDistance(double distance) const {
    double d = std::fmod(distance, mLength);
    if (d < 0.0) d += mLength;
    // fmod of a tiny negative number plus mLength can round up to mLength.
    return d < mLength ? d : 0.0;
}

glm::dvec2 CameraPath::positionAt(double distance) const {
    return evaluateSpline(parameterAt(wrapDistance(distance)));
}

double CameraPath::altitudeAt(double distance) const {
    const double f = wrapDistance(distance) / mStationSpacing;
    const size_t n = mAltitude.size();
    const size_t k = std::min(static_cast<size_t>(f), n - 1);
    const double frac = f - static_cast<double>(k);
    return mAltitude[k] + (mAltitude[(k + 1) % n] - mAltitude[k]) * frac;
}

CameraPose CameraPath::sample(double timeSeconds) const {
    const double distance = wrapDistance(std::fmod(timeSeconds, period()) * mSpeed);
    const glm::dvec2 xz = positionAt(distance);
    const double altitude = altitudeAt(distance);

    // Central differences: symmetric, so no lag; the baseline is wide enough
    // to average out the profile's station-to-station kinks.
    const double h = std::max(4.0 * mStationSpacing, 10.0);
    const glm::dvec2 direction = positionAt(distance + h) - positionAt(distance - h);
    const double climb = altitudeAt(distance + h) - altitudeAt(distance - h);
    const double climbPitch = std::atan2(climb, glm::length(direction));

    CameraPose pose;
    pose.position = glm::vec3(static_cast<float>(xz.x), static_cast<float>(altitude),
                              static_cast<float>(xz.y));
    // Camera convention: forward = (-sin yaw, ., -cos yaw).
    pose.yaw = static_cast<float>(std::atan2(-direction.x, -direction.y));
    const double pitch = std::clamp(climbPitch, -kMaxClimbPitch, kMaxClimbPitch) - kLookDown;
    pose.pitch = static_cast<float>(pitch);
    return pose;
}

} // namespace tessera::scene
