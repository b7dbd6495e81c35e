#pragma once
/// @file AdaptiveLevels.h
/// The paper's adaptive mode: a level per edge (from a metric), clamped by a
/// minimum and maximum chosen per draw.

#include "tessera/core/Result.h"
#include "tessera/tessellator/TessellationTypes.h"

namespace tessera::tessellator {

class AdaptiveLevels {
public:
    /// Checks the per-draw range: 1 <= minLevel <= maxLevel <= 64, no NaN.
    static Result<AdaptiveLevels> create(float minLevel, float maxLevel);

    float minLevel() const { return mMin; }
    float maxLevel() const { return mMax; }

    /// One edge's (or inner) level clamped to the range; NaN and levels <= 0
    /// give minLevel, so adaptive levels never cull a patch.
    /// Clamping is per value, so two patches that compute the same level for
    /// a shared edge still agree after it.
    float clamp(float level) const;

    /// Every outer and inner level of `factors` clamped to the range.
    TessFactors clamp(const TessFactors& factors) const;

private:
    AdaptiveLevels(float minLevel, float maxLevel) : mMin(minLevel), mMax(maxLevel) {}
    float mMin;
    float mMax;
};

} // namespace tessera::tessellator
