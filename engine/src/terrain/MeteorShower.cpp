#include "tessera/terrain/MeteorShower.h"

#include <algorithm>
#include <cmath>

namespace tessera::terrain {
namespace {

// SplitMix64 (Steele, Lea and Flood 2014): a tiny integer generator whose
// output is fixed by its definition, unlike std distributions, whose output
// differs between standard libraries. Floats are made from the top bits with
// exact arithmetic only, so every platform gets the same impacts.
class SplitMix64 {
public:
    explicit SplitMix64(uint64_t seed) : mState(seed) {}

    uint64_t next() {
        uint64_t z = (mState += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    /// Uniform in [0, 1) with 24 bits: exactly representable in float.
    float unit() { return float(next() >> 40) * 0x1.0p-24f; }
    /// Uniform in [-1, 1).
    float signedUnit() { return unit() * 2.0f - 1.0f; }

private:
    uint64_t mState;
};

// Clamps into [lo, hi], or takes the middle when the range is inverted (a
// region narrower than the crater).
float clampOrCentre(float v, float lo, float hi) {
    return lo <= hi ? std::clamp(v, lo, hi) : 0.5f * (lo + hi);
}

} // namespace

std::vector<MeteorImpact> scheduleMeteorShower(const MeteorShowerSettings& settings,
                                               const std::function<glm::vec2(double)>& aimAt) {
    std::vector<MeteorImpact> impacts;
    impacts.reserve(settings.count);
    // Mix the seed once so that neighbouring seeds start far apart.
    SplitMix64 rng(uint64_t(settings.seed) * 0xD1B54A32D192ED03ull + 1u);
    const double slot = settings.durationSeconds / double(std::max(settings.count, 1u));
    for (uint32_t k = 0; k < settings.count; ++k) {
        MeteorImpact impact;
        // One impact per equal slot, jittered within its middle 80%: evenly
        // spread, never two at once, sorted by construction, and strictly
        // inside [start, start + duration) whatever the rounding.
        impact.timeSeconds = settings.startSeconds + slot * (double(k) + 0.1 + 0.8 * double(rng.unit()));

        const float radius = settings.minRadius + (settings.maxRadius - settings.minRadius) * rng.unit();
        // Uniform in the disc by rejection: no sin/cos, whose last bit varies
        // between maths libraries.
        glm::vec2 offset;
        do {
            offset = {rng.signedUnit(), rng.signedUnit()};
        } while (offset.x * offset.x + offset.y * offset.y > 1.0f);
        const glm::vec2 aim = aimAt ? aimAt(impact.timeSeconds) : glm::vec2(0.0f);
        const glm::vec2 centre = aim + offset * settings.scatter;

        impact.splat.center = {clampOrCentre(centre.x, settings.regionMin.x + radius, settings.regionMax.x - radius),
                               clampOrCentre(centre.y, settings.regionMin.y + radius, settings.regionMax.y - radius)};
        impact.splat.radius = radius;
        // Depth and rim scale with the radius, so every crater has the same
        // shape: a bowl about a ninth as deep as it is wide, with a low lip.
        impact.splat.profile = {0.22f * radius, 0.06f * radius, 0.7f};
        impacts.push_back(impact);
    }
    // Already in order for any duration >= 0; a negative one is sorted too,
    // as the header promises.
    std::stable_sort(impacts.begin(), impacts.end(),
                     [](const MeteorImpact& a, const MeteorImpact& b) { return a.timeSeconds < b.timeSeconds; });
    return impacts;
}

} // namespace tessera::terrain
