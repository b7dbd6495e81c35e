#include "tessera/terrain/CraterSplat.h"

#include "tessera/shaders/CraterProfile.h"

#include <algorithm>
#include <cmath>

namespace tessera::terrain {
namespace {

// Index range [lo, hi] of samples within `radius` of `center` along one axis,
// or lo > hi when none. Double precision and clamping before the conversion
// keep absurd inputs (a splat kilometres away) from overflowing.
std::pair<uint32_t, uint32_t> axisRange(float center, float radius, float spacing, uint32_t count) {
    const double lo = std::floor((double(center) - radius) / spacing);
    const double hi = std::ceil((double(center) + radius) / spacing);
    if (hi < 0.0 || lo > double(count - 1)) return {1, 0};
    return {uint32_t(std::max(lo, 0.0)), uint32_t(std::min(hi, double(count - 1)))};
}

} // namespace

CraterProfile scaledCraterProfile(float radius) { return {0.22f * radius, 0.06f * radius, 0.7f}; }

SampleRect craterSamples(const HeightField& field, const CraterSplat& splat) {
    // `!(radius > 0)` also rejects a NaN radius.
    if (!(splat.radius > 0.0f) || !std::isfinite(splat.center.x) || !std::isfinite(splat.center.y)) return {};
    const float spacing = field.scale().horizontalSpacing;
    const auto [i0, i1] = axisRange(splat.center.x, splat.radius, spacing, field.width());
    const auto [j0, j1] = axisRange(splat.center.y, splat.radius, spacing, field.height());
    if (i0 > i1 || j0 > j1) return {};
    return {i0, j0, i1, j1};
}

SampleRect applyCrater(HeightField& field, const CraterSplat& splat) {
    const SampleRect rect = craterSamples(field, splat);
    if (rect.empty()) return rect;
    const float spacing = field.scale().horizontalSpacing;
    const float radiusSq = splat.radius * splat.radius;
    const shader::CraterSplatParams params{
        {splat.center.x, splat.center.y, splat.radius, spacing},
        {splat.profile.depth, splat.profile.rimHeight, splat.profile.rimAt, field.scale().heightScale}};
    // The GPU splat pass computes each texel the same way, in float: world
    // position i * spacing, squared distance dx*dx + dz*dz, tsCraterDelta,
    // then an integer add. Samples at or beyond the radius are skipped rather
    // than rewritten, so they stay bit-identical.
    for (uint32_t j = rect.j0; j <= rect.j1; ++j) {
        const float dz = float(j) * spacing - splat.center.y;
        for (uint32_t i = rect.i0; i <= rect.i1; ++i) {
            const float dx = float(i) * spacing - splat.center.x;
            const float distanceSq = dx * dx + dz * dz;
            if (!(distanceSq < radiusSq)) continue;
            const int old = field.samples()[size_t(j) * field.width() + i];
            const int changed = std::clamp(old + shader::tsCraterDelta(distanceSq, params), 0, 65535);
            field.setSample(i, j, static_cast<uint16_t>(changed));
        }
    }
    return rect;
}

} // namespace tessera::terrain
