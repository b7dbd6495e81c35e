#include "UvRasterizer.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tessera::creature {

namespace {

/// Texels whose centre lies within this many texels of a triangle may be read
/// by a bilinear fetch inside it (the fetch reaches texels with |dx| < 1 and
/// |dy| < 1 of the sample point).
constexpr float kFootprintRadius = 1.41422f;

float cross2(glm::vec2 a, glm::vec2 b) { return a.x * b.y - a.y * b.x; }

glm::vec2 closestOnSegment(glm::vec2 p, glm::vec2 a, glm::vec2 b) {
    glm::vec2 ab = b - a;
    float len2 = glm::dot(ab, ab);
    float s = len2 > 0.0f ? std::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
    return a + s * ab;
}

/// A cage triangle's UVs in texel units (texel (x, y) has its centre at x + 0.5, y + 0.5).
struct UvTriangle {
    glm::vec2 a, b, c;
    float area;

    glm::vec2 barycentric(glm::vec2 p) const {
        return {cross2(p - a, c - a) / area, cross2(b - a, p - a) / area};
    }
    bool contains(glm::vec2 p) const {
        glm::vec2 w = barycentric(p);
        return w.x >= 0.0f && w.y >= 0.0f && 1.0f - w.x - w.y >= 0.0f;
    }
    /// The triangle point nearest `p` (p itself when inside).
    glm::vec2 closest(glm::vec2 p) const {
        if (contains(p)) return p;
        glm::vec2 best = closestOnSegment(p, a, b);
        for (glm::vec2 q : {closestOnSegment(p, b, c), closestOnSegment(p, c, a)}) {
            if (glm::length(p - q) < glm::length(p - best)) best = q;
        }
        return best;
    }
};

} // namespace

UvRasterizer::UvRasterizer(const character::CageMesh& cage, uint32_t size)
    : mSize(size), mTexels(static_cast<size_t>(size) * size) {
    const float scale = static_cast<float>(size);
    const int last = static_cast<int>(size) - 1;
    std::vector<UvTriangle> triangles(cage.triangleCount());
    for (uint32_t t = 0; t < cage.triangleCount(); ++t) {
        UvTriangle& tri = triangles[t];
        tri.a = cage.vertices[cage.indices[3 * t]].uv * scale;
        tri.b = cage.vertices[cage.indices[3 * t + 1]].uv * scale;
        tri.c = cage.vertices[cage.indices[3 * t + 2]].uv * scale;
        tri.area = cross2(tri.b - tri.a, tri.c - tri.a);
    }
    auto texelRange = [&](float lo, float hi) {
        return std::pair<int, int>{std::max(0, static_cast<int>(std::ceil(lo - 0.5f))),
                                   std::min(last, static_cast<int>(std::floor(hi - 0.5f)))};
    };

    for (uint32_t t = 0; t < triangles.size(); ++t) {
        const UvTriangle& tri = triangles[t];
        if (!(std::fabs(tri.area) > 1e-12f)) continue;  // no UV area: no texels of its own
        glm::vec2 lo = glm::min(tri.a, glm::min(tri.b, tri.c)), hi = glm::max(tri.a, glm::max(tri.b, tri.c));
        auto [x0, x1] = texelRange(lo.x, hi.x);
        auto [y0, y1] = texelRange(lo.y, hi.y);
        for (int y = y0; y <= y1; ++y) {
            for (int x = x0; x <= x1; ++x) {
                TexelSample& texel = mTexels[static_cast<size_t>(y) * size + static_cast<size_t>(x)];
                if (texel.kind == TexelKind::Inside) continue;
                glm::vec2 bary = tri.barycentric({x + 0.5f, y + 0.5f});
                if (bary.x < 0.0f || bary.y < 0.0f || 1.0f - bary.x - bary.y < 0.0f) continue;
                texel = {static_cast<int32_t>(t), bary.x, bary.y, TexelKind::Inside};
                ++mInside;
            }
        }
    }

    // Conservative dilation: texels just outside every chart still feed
    // bilinear fetches on the chart's border, so they must hold baked values.
    std::vector<float> nearest(mTexels.size(), std::numeric_limits<float>::infinity());
    for (uint32_t t = 0; t < triangles.size(); ++t) {
        const UvTriangle& tri = triangles[t];
        if (!(std::fabs(tri.area) > 1e-12f)) continue;
        glm::vec2 lo = glm::min(tri.a, glm::min(tri.b, tri.c)) - kFootprintRadius;
        glm::vec2 hi = glm::max(tri.a, glm::max(tri.b, tri.c)) + kFootprintRadius;
        auto [x0, x1] = texelRange(lo.x, hi.x);
        auto [y0, y1] = texelRange(lo.y, hi.y);
        for (int y = y0; y <= y1; ++y) {
            for (int x = x0; x <= x1; ++x) {
                size_t index = static_cast<size_t>(y) * size + static_cast<size_t>(x);
                if (mTexels[index].kind == TexelKind::Inside) continue;
                glm::vec2 p{x + 0.5f, y + 0.5f};
                glm::vec2 q = tri.closest(p);
                float d = glm::length(p - q);
                if (d >= kFootprintRadius || d >= nearest[index]) continue;
                nearest[index] = d;
                glm::vec2 bary = tri.barycentric(q);
                mTexels[index] = {static_cast<int32_t>(t), bary.x, bary.y, TexelKind::Dilated};
            }
        }
    }
    for (uint32_t index = 0; index < mTexels.size(); ++index) {
        const TexelSample& texel = mTexels[index];
        if (texel.kind != TexelKind::Dilated) continue;
        const UvTriangle& tri = triangles[static_cast<size_t>(texel.triangle)];
        glm::vec2 p{static_cast<float>(index % size) + 0.5f, static_cast<float>(index / size) + 0.5f};
        glm::vec2 q = tri.closest(p);
        glm::vec2 m = tri.closest(2.0f * q - p);
        // A slope measured over a base much shorter than the step it is
        // extrapolated by (a sliver triangle, a sharp corner) amplifies the
        // sculpt's fine detail into spikes: extend such texels flat instead.
        // (outward is 0 when the centre lies on an edge by rounding.)
        float outward = glm::length(p - q), inward = glm::length(q - m);
        glm::vec2 bary = tri.barycentric(m);
        bool extrapolate = outward > 0.0f && inward >= 0.5f * outward;
        mDilatedTexels.push_back({index, bary.x, bary.y, extrapolate ? outward / inward : 0.0f});
    }
}

} // namespace tessera::creature
