#include "RowStitcher.h"

#include <bit>
#include <cassert>

namespace tessera::tessellator::detail {
namespace {

// The highest half-level point count the transition supports: 32 points on
// half an edge covers even levels up to 64 and odd levels up to 65.
constexpr int kMaxHalfPoints = 32;

// The step (0 .. 32) of the ruler-function walk at which half-edge point
// position `step` gets its turn. Step 0 is position 0; step 1 is the last
// position (32); otherwise the positions come in ruler order: the first
// odd step fills the quarter, odd multiples of 2 the eighths, and so on, and
// even steps fill the upper half 17..31 in order. A row with h points on its
// half edge advances at exactly the steps whose position is below h.
int rulerPosition(int step) {
    if (step == 0) return 0;
    if (step == 1) return kMaxHalfPoints;
    const auto k = static_cast<unsigned>(step - 1);
    const int level = std::countr_zero(k);
    return (16 >> level) + static_cast<int>(k >> (level + 1));
}

} // namespace

void RowStitcher::triangle(uint32_t a, uint32_t b, uint32_t c) {
    assert(a != b && b != c && a != c);
    mIndices.push_back(a);
    if (mReverse) {
        mIndices.push_back(c);
        mIndices.push_back(b);
    } else {
        mIndices.push_back(b);
        mIndices.push_back(c);
    }
}

void RowStitcher::transition(std::span<const uint32_t> outside, const EdgeSpacing& outsideSpacing,
                             std::span<const uint32_t> inside, const EdgeSpacing& insideSpacing) {
    // Odd spacing's half count includes the point past the middle segment;
    // the walk counts points strictly before the middle.
    const int outsideHalf = outsideSpacing.halfPoints() - (outsideSpacing.odd() ? 1 : 0);
    const int insideHalf = insideSpacing.halfPoints() - (insideSpacing.odd() ? 1 : 0);
    assert(outsideHalf <= kMaxHalfPoints && insideHalf <= kMaxHalfPoints);

    size_t o = 0, i = 0;
    auto advanceOutside = [&] {
        triangle(outside[o], outside[o + 1], inside[i]);
        ++o;
    };
    auto advanceInside = [&] {
        triangle(inside[i], outside[o], inside[i + 1]);
        ++i;
    };

    // First half, from the row starts towards the middle. Step 0 only ever
    // advances the outside: the inside row starts one point in already.
    if (outsideHalf > 0) advanceOutside();
    for (int step = 1; step <= kMaxHalfPoints; ++step) {
        const int position = rulerPosition(step);
        if (position < insideHalf) advanceInside();
        if (position < outsideHalf) advanceOutside();
    }

    // The middle: a quad if both have a middle segment, a triangle if only one.
    const bool insideOdd = insideSpacing.odd(), outsideOdd = outsideSpacing.odd();
    if (insideOdd && outsideOdd) {
        triangle(inside[i], outside[o], inside[i + 1]);
        triangle(inside[i + 1], outside[o], outside[o + 1]);
        ++i;
        ++o;
    } else if (outsideOdd) {
        triangle(inside[i], outside[o], outside[o + 1]);
        ++o;
    } else if (insideOdd) {
        triangle(inside[i], outside[o], inside[i + 1]);
        ++i;
    }

    // Second half, the mirror image of the first.
    for (int step = kMaxHalfPoints; step >= 1; --step) {
        const int position = rulerPosition(step);
        if (position < outsideHalf) advanceOutside();
        if (position < insideHalf) advanceInside();
    }
    if (outsideHalf > 0) advanceOutside();
    assert(o + 1 == outside.size() && i + 1 == inside.size());
}

void RowStitcher::regular(std::span<const uint32_t> outside, std::span<const uint32_t> inside, bool trapezoid,
                          Diagonals diagonals) {
    assert(outside.size() == inside.size() + (trapezoid ? 2 : 0));
    const size_t n = inside.size();
    size_t o = 0, i = 0;
    if (trapezoid) {
        triangle(outside[o], outside[o + 1], inside[i]);
        ++o;
    }
    // A quad split by the diagonal from outside[o] to inside[i + 1], or by the
    // one from inside[i] to outside[o + 1].
    auto quadOutsideDiagonal = [&] {
        triangle(outside[o], inside[i + 1], inside[i]);
        triangle(outside[o], outside[o + 1], inside[i + 1]);
        ++i;
        ++o;
    };
    auto quadInsideDiagonal = [&] {
        triangle(inside[i], outside[o], outside[o + 1]);
        triangle(inside[i], outside[o + 1], inside[i + 1]);
        ++i;
        ++o;
    };
    auto quadInsideDiagonalOutsideFirst = [&] {
        triangle(outside[o], outside[o + 1], inside[i]);
        triangle(inside[i], outside[o + 1], inside[i + 1]);
        ++i;
        ++o;
    };
    switch (diagonals) {
    case Diagonals::InsideToOutside:
        for (size_t q = 0; q + 1 < n; ++q) quadInsideDiagonal();
        break;
    case Diagonals::InsideToOutsideExceptMiddle: {
        // For an odd number of quads: the middle one takes the other diagonal.
        size_t q = 0;
        for (; q + 1 < n / 2; ++q) quadInsideDiagonalOutsideFirst();
        quadOutsideDiagonal();
        for (q += 2; q < n; ++q) quadInsideDiagonalOutsideFirst();
        break;
    }
    case Diagonals::Mirrored: {
        size_t q = 0;
        for (; q < n / 2; ++q) quadOutsideDiagonal();
        for (; q + 1 < n; ++q) quadInsideDiagonal();
        break;
    }
    }
    if (trapezoid) triangle(outside[o], outside[o + 1], inside[i]);
}

} // namespace tessera::tessellator::detail
