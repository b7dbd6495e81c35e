#pragma once
/// @file SampleRect.h
/// An inclusive rectangle of height-field sample indices.

#include <algorithm>
#include <cstdint>

namespace tessera::terrain {

/// Samples [i0, i1] x [j0, j1], inclusive; empty when i0 > i1 or j0 > j1.
struct SampleRect {
    uint32_t i0 = 1, j0 = 1, i1 = 0, j1 = 0;

    bool empty() const { return i0 > i1 || j0 > j1; }
    bool contains(uint32_t i, uint32_t j) const { return i >= i0 && i <= i1 && j >= j0 && j <= j1; }
    /// The smallest rectangle holding both (either may be empty).
    static SampleRect unite(const SampleRect& a, const SampleRect& b) {
        if (a.empty()) return b;
        if (b.empty()) return a;
        return {std::min(a.i0, b.i0), std::min(a.j0, b.j0), std::max(a.i1, b.i1), std::max(a.j1, b.j1)};
    }
};

} // namespace tessera::terrain
