#include "ImpostorRasterizer.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tessera::character {
namespace {

// Twice the signed area of (a, b, p): positive when p is left of a -> b.
float edge(const glm::vec2& a, const glm::vec2& b, const glm::vec2& p) {
    return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}

bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

} // namespace

void ImpostorRasterizer::clear() {
    std::fill(mSamples.begin(), mSamples.end(), Sample{-std::numeric_limits<float>::infinity(), kNone, 0.0f, 0.0f});
}

void ImpostorRasterizer::draw(uint32_t triangle, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    if (!finite(a) || !finite(b) || !finite(c)) return;
    const float side = float(kSide);
    const glm::vec2 p0(a.x * side, a.y * side), p1(b.x * side, b.y * side), p2(c.x * side, c.y * side);
    const float area = edge(p0, p1, p2);
    if (area == 0.0f) return;
    // Samples sit at n + 0.5; clamping in float first keeps a vertex far
    // outside the sphere from overflowing the integer conversion.
    auto first = [side](float lo) { return int(std::ceil(std::clamp(lo, -1.0f, side + 1.0f) - 0.5f)); };
    auto last = [side](float hi) { return int(std::floor(std::clamp(hi, -1.0f, side + 1.0f) - 0.5f)); };
    const int x0 = std::max(first(std::min({p0.x, p1.x, p2.x})), 0);
    const int x1 = std::min(last(std::max({p0.x, p1.x, p2.x})), int(kSide) - 1);
    const int y0 = std::max(first(std::min({p0.y, p1.y, p2.y})), 0);
    const int y1 = std::min(last(std::max({p0.y, p1.y, p2.y})), int(kSide) - 1);
    if (x0 > x1 || y0 > y1) return;
    const float inverse = 1.0f / area;
    for (int y = y0; y <= y1; ++y) {
        for (int x = x0; x <= x1; ++x) {
            const glm::vec2 p(float(x) + 0.5f, float(y) + 0.5f);
            // Divided by the signed area, so both windings come out inside
            // as three non-negative weights: no back faces are culled, the
            // depth test alone decides.
            const float w0 = edge(p1, p2, p) * inverse;
            const float w1 = edge(p2, p0, p) * inverse;
            const float w2 = edge(p0, p1, p) * inverse;
            if (w0 < 0.0f || w1 < 0.0f || w2 < 0.0f) continue;
            const float depth = w0 * a.z + w1 * b.z + w2 * c.z;
            Sample& s = mSamples[size_t(y) * kSide + size_t(x)];
            if (!(depth > s.depth)) continue;
            s = {depth, triangle, w1, w2};
        }
    }
}

} // namespace tessera::character
