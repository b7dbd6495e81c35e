#pragma once
/// @file ContinuousLevel.h
/// The paper's continuous mode: one tessellation level for a whole draw,
/// within the range D3D10-era emulation supports.

#include "tessera/tessellator/TessellationTypes.h"

namespace tessera::tessellator {

class ContinuousLevel {
public:
    /// The emulated draws' range: below 1 there is nothing to subdivide, and
    /// 14.99 is the top level of the paper's D3D10-era emulation.
    static constexpr float kMinLevel = 1.0f;
    static constexpr float kMaxLevel = 14.99f;

    /// `level` clamped to [kMinLevel, kMaxLevel]; NaN gives kMinLevel.
    static float clamp(float level);

    /// The patch levels of a continuous draw: every outer and inner level set
    /// to clamp(level) (the unused ones of a triangle too, harmlessly).
    static TessFactors factors(float level);
};

} // namespace tessera::tessellator
