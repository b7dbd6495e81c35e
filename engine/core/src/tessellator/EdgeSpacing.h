#pragma once
// Where the points of one tessellated edge (or one axis of the inner grid)
// fall, for one fixed-point level and parity: the reference tessellator's
// per-factor context, its point count and its 1D point placement.

#include "FixedPoint.h"

namespace tessera::tessellator::detail {

/// Odd spacing has a segment centred on the edge midpoint, even spacing a
/// point there. Fractional modes fix the parity; integer spacing takes it from
/// the rounded level (an inner level of exactly 1 counts as even).
enum class Parity { Even, Odd };

class EdgeSpacing {
public:
    EdgeSpacing() = default;
    /// `level` is the clamped, rounded level in 16.16.
    EdgeSpacing(Fxp level, Parity parity);

    Parity parity() const { return mParity; }
    bool odd() const { return mParity == Parity::Odd; }

    /// Points along the whole edge, both ends included (segments + 1).
    int pointCount() const { return mPointCount; }

    /// Points on the first half of the edge before the midpoint, as the
    /// reference counts them (ceil of half the level; for odd parity this
    /// includes the first point past the middle segment).
    int halfPoints() const { return mHalfPoints; }

    /// Location of point `index` (0 .. pointCount() - 1) along the edge, in
    /// 16.16. The first half blends the floor and ceiling half-levels' uniform
    /// spacings by the half-level's fraction, the new points appearing in
    /// ruler order from the ends; the second half mirrors the first, so the
    /// edge reads the same from either end.
    Fxp place(int index) const;

private:
    Parity mParity = Parity::Even;
    int mPointCount = 0;
    int mHalfPoints = 0;
    int mSplitPoint = 0;       ///< beyond this index the floor half-level has one point fewer
    Fxp mHalfFraction = 0;     ///< fractional part of half the level
    Fxp mInvFloorSegments = 0; ///< 1 / segments of the floor level
    Fxp mInvCeilSegments = 0;  ///< 1 / segments of the ceiling level
};

} // namespace tessera::tessellator::detail
