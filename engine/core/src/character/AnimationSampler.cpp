#include "tessera/character/AnimationSampler.h"

#include <algorithm>
#include <cmath>

namespace tessera::character {

namespace {

glm::quat toQuat(const glm::vec4& v) {
    return glm::quat(v.w, v.x, v.y, v.z);
}
glm::vec4 fromQuat(const glm::quat& q) {
    return glm::vec4(q.x, q.y, q.z, q.w);
}

size_t valuesPerKey(const AnimationChannel& channel) {
    return channel.interpolation == AnimationInterpolation::CubicSpline ? 3 : 1;
}

} // namespace

bool isChannelSampleable(const AnimationChannel& channel) {
    return !channel.times.empty() && channel.values.size() >= channel.times.size() * valuesPerKey(channel);
}

glm::quat slerpShortest(const glm::quat& a, const glm::quat& b, float t) {
    glm::quat end = b;
    float cosAngle = glm::dot(a, b);
    if (cosAngle < 0.0f) {
        end = -b;
        cosAngle = -cosAngle;
    }
    // Nearly parallel: sin(angle) underflows the weights' division; a
    // normalised lerp is indistinguishable there.
    if (cosAngle > 0.9995f) return glm::normalize(a * (1.0f - t) + end * t);
    const float angle = std::acos(cosAngle);
    const float sinAngle = std::sin(angle);
    const float wa = std::sin((1.0f - t) * angle) / sinAngle;
    const float wb = std::sin(t * angle) / sinAngle;
    return a * wa + end * wb;
}

glm::vec4 sampleChannel(const AnimationChannel& channel, float seconds) {
    if (!isChannelSampleable(channel)) return glm::vec4(0.0f);
    const std::vector<float>& times = channel.times;
    const bool cubic = channel.interpolation == AnimationInterpolation::CubicSpline;
    const bool rotation = channel.path == AnimationPath::Rotation;
    // The value of key k (the middle element of a cubic key's triple).
    auto value = [&](size_t k) { return channel.values[cubic ? 3 * k + 1 : k]; };
    auto finish = [&](glm::vec4 v) { return rotation && cubic ? fromQuat(glm::normalize(toQuat(v))) : v; };

    // Written as !(>) so a NaN time reads as the first key instead of
    // indexing past the end below.
    if (!(seconds > times.front())) return finish(value(0));
    if (seconds >= times.back()) return finish(value(times.size() - 1));
    // First key strictly after `seconds`; its predecessor starts the interval.
    const size_t next = static_cast<size_t>(std::upper_bound(times.begin(), times.end(), seconds) - times.begin());
    const size_t k = next - 1;
    if (channel.interpolation == AnimationInterpolation::Step) return value(k);

    const float dt = times[next] - times[k];
    const float t = dt > 0.0f ? (seconds - times[k]) / dt : 0.0f;
    if (channel.interpolation == AnimationInterpolation::Linear) {
        if (rotation) return fromQuat(slerpShortest(toQuat(value(k)), toQuat(value(next)), t));
        return glm::mix(value(k), value(next), t);
    }
    // glTF 2.0 Appendix C: Hermite spline with the out-tangent of key k and
    // the in-tangent of key k + 1, both scaled by the interval.
    const float t2 = t * t, t3 = t2 * t;
    const glm::vec4 p0 = value(k), p1 = value(next);
    const glm::vec4 m0 = channel.values[3 * k + 2] * dt;
    const glm::vec4 m1 = channel.values[3 * next] * dt;
    const glm::vec4 v = (2.0f * t3 - 3.0f * t2 + 1.0f) * p0 + (t3 - 2.0f * t2 + t) * m0 +
                        (-2.0f * t3 + 3.0f * t2) * p1 + (t3 - t2) * m1;
    return finish(v);
}

} // namespace tessera::character
