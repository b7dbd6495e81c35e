#include "PatchFactors.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tessera::tessellator::detail {
namespace {

// 2^-16, the smallest fixed-point fraction.
constexpr float kFxpEpsilon = 1.0f / 65536.0f;

// Clamp with the reference's IEEE-754R min/max semantics: NaN (and anything
// below `low`, denormals included) becomes `low`.
float clampLevel(float level, float low, float high) {
    if (!(level > low)) return low;
    return level > high ? high : level;
}

bool integerLevelIsEven(float level) {
    return (static_cast<int>(level) & 1) == 0;
}

} // namespace

PatchFactors::PatchFactors(Domain domain, Partitioning partitioning, const TessFactors& factors) : mDomain(domain) {
    const int edges = edgeCount();
    const int axes = domain == Domain::Quad ? 2 : 1;
    // Culling sees denormals as zero: D3D11 flushes them in float operations,
    // and lavapipe's shaders run with denormals flushed (a level of 1e-40
    // culls the patch there).
    for (int e = 0; e < edges; ++e) {
        if (!(factors.outer[static_cast<size_t>(e)] >= std::numeric_limits<float>::min())) {
            mCulled = true;
            return;
        }
    }

    float low = 1.0f, high = 64.0f;
    if (partitioning == Partitioning::FractionalOdd) high = 63.0f;
    if (partitioning == Partitioning::FractionalEven) low = 2.0f;
    const bool integer = partitioning == Partitioning::Integer;

    std::array<float, 4> outer{};
    for (int e = 0; e < edges; ++e) {
        auto& level = outer[static_cast<size_t>(e)];
        level = clampLevel(factors.outer[static_cast<size_t>(e)], low, high);
        if (integer) level = std::ceil(level);
    }

    // fractional_odd: if any level will be above 1 in fixed point, the inner
    // levels must be too, so that there is a "picture frame" ring to stitch
    // the edges to. For quads the raw inner levels take part in the test; for
    // triangles only the outer levels do (the reference's rule).
    float innerLow = low;
    if (partitioning == Partitioning::FractionalOdd) {
        const float threshold = 1.0f + kFxpEpsilon / 2.0f;
        bool frame = false;
        for (int e = 0; e < edges; ++e) frame = frame || outer[static_cast<size_t>(e)] > threshold;
        if (domain == Domain::Quad)
            for (int a = 0; a < axes; ++a) frame = frame || factors.inner[static_cast<size_t>(a)] > threshold;
        if (frame) innerLow = 1.0f + kFxpEpsilon;
    }
    std::array<float, 2> inner{};
    for (int a = 0; a < axes; ++a) {
        auto& level = inner[static_cast<size_t>(a)];
        level = clampLevel(factors.inner[static_cast<size_t>(a)], innerLow, high);
        if (integer) level = std::ceil(level);
    }

    const Parity fixedParity = partitioning == Partitioning::FractionalOdd ? Parity::Odd : Parity::Even;
    std::array<Fxp, 4> outerFxp{};
    std::array<Fxp, 2> innerFxp{};
    for (int e = 0; e < edges; ++e) outerFxp[static_cast<size_t>(e)] = toFixed(outer[static_cast<size_t>(e)]);
    for (int a = 0; a < axes; ++a) innerFxp[static_cast<size_t>(a)] = toFixed(inner[static_cast<size_t>(a)]);

    if (partitioning != Partitioning::FractionalEven) {
        bool allOne = true;
        for (int e = 0; e < edges; ++e) allOne = allOne && outerFxp[static_cast<size_t>(e)] == kFxpOne;
        for (int a = 0; a < axes; ++a) allOne = allOne && innerFxp[static_cast<size_t>(a)] == kFxpOne;
        if (allOne) {
            mMinimal = true;
            return;
        }
    }

    for (int e = 0; e < edges; ++e) {
        const float level = outer[static_cast<size_t>(e)];
        const Parity parity = integer ? (integerLevelIsEven(level) ? Parity::Even : Parity::Odd) : fixedParity;
        mOuter[static_cast<size_t>(e)] = EdgeSpacing(outerFxp[static_cast<size_t>(e)], parity);
    }
    for (int a = 0; a < axes; ++a) {
        const float level = inner[static_cast<size_t>(a)];
        const Parity parity =
            integer ? (integerLevelIsEven(level) || level == 1.0f ? Parity::Even : Parity::Odd) : fixedParity;
        const EdgeSpacing spacing(innerFxp[static_cast<size_t>(a)], parity);
        mInner[static_cast<size_t>(a)] = spacing;
        mInnerPoints[static_cast<size_t>(a)] = std::max(spacing.odd() ? 4 : 3, spacing.pointCount());
    }
}

} // namespace tessera::tessellator::detail
