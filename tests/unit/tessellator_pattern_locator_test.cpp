// PatternLocator: the triangle of a Tessellator pattern holding a domain
// point, against a brute-force search over every triangle, for uniform,
// mixed and emulated-range levels.

#include "tessera/core/Random.h"
#include "tessera/tessellator/PatternLocator.h"
#include "tessera/tessellator/Tessellator.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace tessera;
using namespace tessera::tessellator;

namespace {

float doubleArea(glm::vec2 a, glm::vec2 b, glm::vec2 c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// The linear function f(u, v) = 3u - 7v + 2 interpolated over the located
// triangle: exact (to rounding) whichever triangle holds the point.
float interpolate(const PatternLocator& locator, glm::vec2 uv) {
    const PatternLocator::Hit hit = locator.locate(uv);
    float f = 0.0f;
    for (int k = 0; k < 3; ++k) {
        const glm::vec2 p = locator.patch().uv[hit.corners[size_t(k)]];
        f += hit.weights[k] * (3.0f * p.x - 7.0f * p.y + 2.0f);
    }
    return f;
}

// Whether some non-degenerate triangle holds `uv` with the hit's corners.
bool holds(const PatternLocator& locator, glm::vec2 uv, const PatternLocator::Hit& hit) {
    const auto& p = locator.patch();
    const glm::vec2 a = p.uv[hit.corners[0]], b = p.uv[hit.corners[1]], c = p.uv[hit.corners[2]];
    const float area = doubleArea(a, b, c);
    if (area == 0.0f) return false;
    const float eps = 1e-5f;
    return doubleArea(uv, b, c) / area >= -eps && doubleArea(a, uv, c) / area >= -eps &&
           doubleArea(a, b, uv) / area >= -eps;
}

} // namespace

TEST(PatternLocator, EveryPointLandsInATriangleThatHoldsIt) {
    Random rng(7u);
    std::vector<TessFactors> cases = {{{1, 1, 1, 1}, {1, 1}},
                                      {{14.99f, 14.99f, 14.99f, 14.99f}, {14.99f, 14.99f}},
                                      {{64, 64, 64, 64}, {64, 64}},
                                      {{1, 63, 2.5f, 7.3f}, {63, 7.3f}},
                                      {{3.2f, 1.0f, 9.9f, 1.1f}, {1.1f, 9.9f}}};
    for (int i = 0; i < 20; ++i) {
        TessFactors f;
        for (float& o : f.outer) o = rng.range(1.0f, 20.0f);
        f.inner = {std::max(f.outer[1], f.outer[3]), std::max(f.outer[0], f.outer[2])};
        cases.push_back(f);
    }
    for (const TessFactors& f : cases) {
        const PatternLocator locator(Tessellator::tessellate(Domain::Quad, Partitioning::FractionalOdd, f));
        ASSERT_FALSE(locator.empty());
        for (int k = 0; k < 400; ++k) {
            const glm::vec2 uv(rng.range(0.0f, 1.0f), rng.range(0.0f, 1.0f));
            const PatternLocator::Hit hit = locator.locate(uv);
            EXPECT_TRUE(holds(locator, uv, hit))
                << "outer " << f.outer[0] << " " << f.outer[1] << " at " << uv.x << "," << uv.y;
            EXPECT_NEAR(hit.weights.x + hit.weights.y + hit.weights.z, 1.0f, 1e-5f);
            EXPECT_NEAR(interpolate(locator, uv), 3.0f * uv.x - 7.0f * uv.y + 2.0f, 1e-4f);
        }
        // The pattern's own points and the square's corners and edges.
        for (const glm::vec2 p : locator.patch().uv)
            EXPECT_NEAR(interpolate(locator, p), 3.0f * p.x - 7.0f * p.y + 2.0f, 1e-4f);
        for (const glm::vec2 p : {glm::vec2(0, 0), glm::vec2(1, 1), glm::vec2(0.5f, 0), glm::vec2(1, 0.25f)})
            EXPECT_NEAR(interpolate(locator, p), 3.0f * p.x - 7.0f * p.y + 2.0f, 1e-4f);
    }
}

TEST(PatternLocator, PointsOutsideTheSquareAreClampedAndAnEmptyPatternIsEmpty) {
    const PatternLocator locator(Tessellator::tessellate(Domain::Quad, Partitioning::FractionalOdd, {}));
    EXPECT_NEAR(interpolate(locator, {-0.5f, 2.0f}), 3.0f * 0.0f - 7.0f * 1.0f + 2.0f, 1e-5f);
    const PatternLocator culled(
        Tessellator::tessellate(Domain::Quad, Partitioning::FractionalOdd, {{0, 1, 1, 1}, {1, 1}}));
    EXPECT_TRUE(culled.empty());
}
