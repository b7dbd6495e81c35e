#pragma once
/// @file SubdivSettings.h
/// How SubdivSurface turns a control mesh into patches: the depths of
/// OpenSubdiv's feature-adaptive refinement and the kind of end cap.

#include <cstdint>

namespace tessera::subdiv {

/// The patch that closes the hole feature-adaptive refinement leaves around
/// an irregular feature at the last isolation level (OpenSubdiv's end caps).
/// Both are evaluated by OpenSubdiv's GLSL OsdEvaluatePatchBasis, so either
/// can be drawn by the same tessellation shaders.
enum class EndCap : uint8_t {
    /// 20-point Gregory basis patches (OpenSubdiv's default and
    /// recommendation): they interpolate the exact limit position and
    /// tangent plane at the extraordinary vertex, and Bfr (the CPU
    /// reference) approximates irregular faces with the same patches, so Far
    /// and Bfr agree to round-off. Not C1 across their own edges (the cause
    /// of OpenSubdiv issue 168's normal-displacement cracks).
    GregoryBasis,
    /// 16-point B-spline patches fitted to the Gregory patch: every patch has
    /// the same type and size (one draw, one shader path) at the price of an
    /// approximation that matches neither the limit nor Bfr exactly.
    BSplineBasis,
};

/// Settings of SubdivSurface::create.
struct SubdivSettings {
    /// Deepest feature-adaptive refinement (1 .. 10), the level sharp
    /// features (semi-sharp creases and corners, irregular crease vertices)
    /// are isolated to; OpenSubdiv's primary isolation level. A semi-sharp
    /// crease of sharpness s is exact after ceil(s) levels, so 3 resolves the
    /// creases artists usually use while keeping the patch count of a
    /// character cage in the thousands.
    uint32_t isolationLevel = 3;
    /// Shallower level (1 .. isolationLevel) where isolation of smooth
    /// irregular features (extraordinary vertices away from creases) stops
    /// and end caps take over: OpenSubdiv's secondary level, Bfr's
    /// "approximation level for smooth features" (whose default is 2).
    /// Every level adds a ring of patches around each extraordinary vertex
    /// while the Gregory end cap already has the exact limit point and
    /// tangent plane there.
    uint32_t smoothIsolationLevel = 2;
    /// See EndCap.
    EndCap endCap = EndCap::GregoryBasis;
};

} // namespace tessera::subdiv
