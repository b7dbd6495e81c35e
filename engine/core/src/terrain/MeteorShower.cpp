#include "tessera/terrain/MeteorShower.h"

#include "tessera/core/Random.h"

#include <algorithm>
#include <cmath>

namespace tessera::terrain {
namespace {

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
    // The core generator: floats from its top 24 bits are exact, so every
    // platform gets the same impacts.
    Random rng(settings.seed);
    const double slot = settings.durationSeconds / double(std::max(settings.count, 1u));
    for (uint32_t k = 0; k < settings.count; ++k) {
        MeteorImpact impact;
        // One impact per equal slot, jittered within its middle 80%: evenly
        // spread, never two at once, sorted by construction, and strictly
        // inside [start, start + duration) whatever the rounding.
        impact.timeSeconds = settings.startSeconds + slot * (double(k) + 0.1 + 0.8 * double(rng.nextFloat()));

        const float radius = settings.minRadius + (settings.maxRadius - settings.minRadius) * rng.nextFloat();
        // Uniform in the disc by rejection: no sin/cos, whose last bit varies
        // between maths libraries.
        glm::vec2 offset;
        do {
            offset = {rng.range(-1.0f, 1.0f), rng.range(-1.0f, 1.0f)};
        } while (offset.x * offset.x + offset.y * offset.y > 1.0f);
        const glm::vec2 aim = aimAt ? aimAt(impact.timeSeconds) : glm::vec2(0.0f);
        const glm::vec2 centre = aim + offset * settings.scatter;

        impact.splat.center = {clampOrCentre(centre.x, settings.regionMin.x + radius, settings.regionMax.x - radius),
                               clampOrCentre(centre.y, settings.regionMin.y + radius, settings.regionMax.y - radius)};
        impact.splat.radius = radius;
        impact.splat.profile = scaledCraterProfile(radius);
        impacts.push_back(impact);
    }
    // Already in order for any duration >= 0; a negative one is sorted too,
    // as the header promises.
    std::stable_sort(impacts.begin(), impacts.end(),
                     [](const MeteorImpact& a, const MeteorImpact& b) { return a.timeSeconds < b.timeSeconds; });
    return impacts;
}

} // namespace tessera::terrain
