#include "EdgeSpacing.h"

#include <bit>
#include <cassert>

namespace tessera::tessellator::detail {
namespace {

// The value with its highest set bit cleared (0 stays 0).
int clearHighestBit(int value) {
    assert(value >= 0);
    return value == 0 ? 0 : value & ~static_cast<int>(std::bit_floor(static_cast<unsigned>(value)));
}

} // namespace

EdgeSpacing::EdgeSpacing(Fxp level, Parity parity) : mParity(parity) {
    // Half the level, rounded up at the last bit. Odd spacing adds a half so
    // that its middle segment counts as a point; a level of 1 under even
    // spacing (integer inner level 1) behaves like 2, a point at the middle.
    Fxp half = (level + 1) / 2;
    if (odd() || half == kFxpHalf) half += kFxpHalf;
    const Fxp floorHalf = fxpFloor(half);
    const Fxp ceilHalf = fxpCeil(half);
    mHalfFraction = half - floorHalf;
    mHalfPoints = static_cast<int>(ceilHalf >> kFractionBits);

    // Which point of the half edge is the one that splits as the fraction
    // grows: the ruler order makes it the one just past the highest power of
    // two of the floor level's half-point count.
    if (ceilHalf == floorHalf) {
        mSplitPoint = mHalfPoints + 1; // no fraction: never reached
    } else if (odd()) {
        const int floorPoints = static_cast<int>(floorHalf >> kFractionBits);
        mSplitPoint = floorHalf == kFxpOne ? 0 : (clearHighestBit(floorPoints - 1) << 1) + 1;
    } else {
        mSplitPoint = (clearHighestBit(static_cast<int>(floorHalf >> kFractionBits)) << 1) + 1;
    }

    int floorSegments = static_cast<int>((floorHalf * 2) >> kFractionBits);
    int ceilSegments = static_cast<int>((ceilHalf * 2) >> kFractionBits);
    if (odd()) {
        --floorSegments;
        --ceilSegments;
    }
    assert(floorSegments >= 1 && ceilSegments <= 64);
    mInvFloorSegments = fxpReciprocal(static_cast<uint32_t>(floorSegments));
    mInvCeilSegments = fxpReciprocal(static_cast<uint32_t>(ceilSegments));

    if (odd())
        mPointCount = static_cast<int>((fxpCeil(kFxpHalf + (level + 1) / 2) * 2) >> kFractionBits);
    else
        mPointCount = static_cast<int>((fxpCeil((level + 1) / 2) * 2) >> kFractionBits) + 1;
}

Fxp EdgeSpacing::place(int index) const {
    // Points past the half are the mirror images of points before it.
    bool mirrored = false;
    if (index >= mHalfPoints) {
        index = (mHalfPoints << 1) - index - (odd() ? 1 : 0);
        mirrored = true;
    }
    // 16 bits cannot make the exact middle from the blend below.
    if (index == mHalfPoints) return kFxpHalf;

    const auto onCeil = static_cast<uint32_t>(index);
    const uint32_t onFloor = index > mSplitPoint ? onCeil - 1 : onCeil;
    // Both locations are at most 0.5, so the blend fits in 32 bits.
    const Fxp floorLocation = onFloor * mInvFloorSegments;
    const Fxp ceilLocation = onCeil * mInvCeilSegments;
    Fxp location = floorLocation * (kFxpOne - mHalfFraction) + ceilLocation * mHalfFraction;
    location = (location + kFxpHalf) >> kFractionBits;
    return mirrored ? kFxpOne - location : location;
}

} // namespace tessera::tessellator::detail
