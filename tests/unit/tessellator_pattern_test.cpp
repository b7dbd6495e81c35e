// The emulated fixed-function tessellator: known patterns, counts, domain
// bounds, exact edges, watertightness and winding. The values below were also
// checked against lavapipe's tessellator through transform feedback (point
// sets, triangle counts, evaluation invocations and oriented triangles).
#include "tessera/core/Random.h"
#include "tessera/tessellator/Tessellator.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <utility>
#include <vector>

using namespace tessera::tessellator;
using tessera::Random;

namespace {

constexpr Partitioning kPartitionings[] = {Partitioning::Integer, Partitioning::FractionalOdd,
                                           Partitioning::FractionalEven};
constexpr Domain kDomains[] = {Domain::Triangle, Domain::Quad};

TessFactors uniform(float level) {
    return TessFactors{{level, level, level, level}, {level, level}};
}

// Segments an edge of level `level` gets: rounded up to an integer, an odd or
// an even number, after clamping to the partitioning's range.
int segments(Partitioning p, float level) {
    switch (p) {
    case Partitioning::Integer:
        return int(std::ceil(std::clamp(level, 1.0f, 64.0f)));
    case Partitioning::FractionalOdd: {
        const int n = int(std::ceil(std::clamp(level, 1.0f, 63.0f)));
        return n % 2 == 1 ? n : n + 1;
    }
    case Partitioning::FractionalEven: {
        const int n = int(std::ceil(std::clamp(level, 2.0f, 64.0f)));
        return n % 2 == 0 ? n : n + 1;
    }
    }
    return 0;
}

// Triangles of a uniform triangle at n segments per edge under the D3D11 ring
// scheme: rings of m, m-2, ... segments, 6(m-1) triangles between consecutive
// ones, and a centre triangle when n is odd: (3n^2 - 1) / 2 or 3n^2 / 2.
uint32_t ringTriangles(uint32_t n) {
    return n % 2 ? (3 * n * n - 1) / 2 : 3 * n * n / 2;
}

float signedArea(glm::vec2 a, glm::vec2 b, glm::vec2 c) {
    return (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
}

std::vector<float> sortedUnique(std::vector<float> values) {
    std::sort(values.begin(), values.end());
    values.erase(std::unique(values.begin(), values.end()), values.end());
    return values;
}

// Coordinates along an edge of every point lying on it.
std::vector<float> quadEdge(const TessellatedPatch& patch, int edge) {
    std::vector<float> along;
    for (const auto& p : patch.uv) {
        if (edge == 0 && p.x == 0.0f) along.push_back(p.y);
        if (edge == 1 && p.y == 0.0f) along.push_back(p.x);
        if (edge == 2 && p.x == 1.0f) along.push_back(p.y);
        if (edge == 3 && p.y == 1.0f) along.push_back(p.x);
    }
    return along;
}

struct RandomCase {
    Domain domain;
    Partitioning partitioning;
    TessFactors factors;
};

std::vector<RandomCase> randomCases(size_t count) {
    Random rng(20240611u);
    auto low = [](Random& r) { return r.range(0.5f, 20.0f); };
    auto wide = [](Random& r) { return r.range(0.5f, 70.0f); };
    std::vector<RandomCase> cases;
    for (size_t i = 0; i < count; ++i) {
        auto level = [&] { return rng.below(4) == 0 ? wide(rng) : low(rng); };
        RandomCase c{kDomains[rng.below(2)], kPartitionings[rng.below(3)], {}};
        for (auto& o : c.factors.outer) o = level();
        for (auto& in : c.factors.inner) in = level();
        cases.push_back(c);
    }
    return cases;
}

} // namespace

TEST(TessellatorPattern, UniformIntegerQuadIsAGrid) {
    for (uint32_t n = 1; n <= 64; ++n) {
        const auto patch = Tessellator::tessellate(Domain::Quad, Partitioning::Integer, uniform(float(n)));
        EXPECT_EQ(patch.triangleCount(), 2 * n * n) << n;
        EXPECT_EQ(patch.uv.size(), size_t(n + 1) * (n + 1)) << n;
    }
}

TEST(TessellatorPattern, UniformIntegerTriangleIsConcentricRings) {
    // Not the n^2 of a uniform barycentric grid: D3D11 and Vulkan tessellate a
    // triangle as concentric rings, about 1.5 n^2 triangles.
    for (uint32_t n = 1; n <= 64; ++n) {
        const auto patch = Tessellator::tessellate(Domain::Triangle, Partitioning::Integer, uniform(float(n)));
        EXPECT_EQ(patch.triangleCount(), ringTriangles(n)) << n;
    }
    EXPECT_EQ(Tessellator::countTriangles(Domain::Triangle, Partitioning::Integer, uniform(1.0f)), 1u);
    EXPECT_EQ(Tessellator::countTriangles(Domain::Triangle, Partitioning::Integer, uniform(2.0f)), 6u);
    EXPECT_EQ(Tessellator::countTriangles(Domain::Triangle, Partitioning::Integer, uniform(3.0f)), 13u);
}

TEST(TessellatorPattern, LevelOneIsTheBarePatch) {
    for (Partitioning p : {Partitioning::Integer, Partitioning::FractionalOdd}) {
        const auto tri = Tessellator::tessellate(Domain::Triangle, p, uniform(1.0f));
        ASSERT_EQ(tri.triangleCount(), 1u);
        using Corners = std::set<std::pair<float, float>>;
        const Corners expected{{0.0f, 1.0f}, {0.0f, 0.0f}, {1.0f, 0.0f}};
        Corners corners;
        for (const auto& q : tri.uv) corners.emplace(q.x, q.y);
        EXPECT_EQ(corners, expected);
        const auto quad = Tessellator::tessellate(Domain::Quad, p, uniform(1.0f));
        EXPECT_EQ(quad.triangleCount(), 2u);
        EXPECT_EQ(quad.uv.size(), 4u);
        // Levels below 1 clamp to 1.
        EXPECT_EQ(Tessellator::countTriangles(Domain::Quad, p, uniform(0.25f)), 2u);
    }
    // Fractional even never goes below 2 segments.
    EXPECT_EQ(Tessellator::countTriangles(Domain::Triangle, Partitioning::FractionalEven, uniform(1.0f)), 6u);
    EXPECT_EQ(Tessellator::countTriangles(Domain::Quad, Partitioning::FractionalEven, uniform(1.0f)), 8u);
}

TEST(TessellatorPattern, KnownFractionalPatterns) {
    // Counts confirmed on lavapipe.
    EXPECT_EQ(
        Tessellator::countTriangles(Domain::Triangle, Partitioning::FractionalOdd, {{2.5f, 3.7f, 5.1f, 0}, {4.2f, 0}}),
        37u);
    EXPECT_EQ(
        Tessellator::countTriangles(Domain::Triangle, Partitioning::FractionalEven, {{2.5f, 3.7f, 5.1f, 0}, {4.2f, 0}}),
        50u);
    EXPECT_EQ(Tessellator::countTriangles(Domain::Quad, Partitioning::FractionalEven,
                                          {{3.3f, 7.9f, 2.1f, 12.0f}, {5.5f, 9.1f}}),
              116u);
    EXPECT_EQ(Tessellator::countTriangles(Domain::Quad, Partitioning::FractionalOdd,
                                          {{3.3f, 7.9f, 2.1f, 12.0f}, {5.5f, 9.1f}}),
              148u);
    // Inner levels of 1 under fractional_odd are forced just above 1: a
    // "picture frame" ring that collapses onto the edges (zero-area triangles).
    EXPECT_EQ(Tessellator::countTriangles(Domain::Quad, Partitioning::FractionalOdd, {{3, 3, 3, 3}, {1, 1}}), 18u);

    // fractional_odd 3.5: five segments, the two new ones growing at the middle,
    // all in 16.16 fixed point (0.3 = 0x4ccd / 65536 ...).
    const auto patch = Tessellator::tessellate(Domain::Quad, Partitioning::FractionalOdd, uniform(3.5f));
    const std::vector<float> expected{0.0f, 0x4ccdp-16f, 0x5999p-16f, 0xa667p-16f, 0xb333p-16f, 1.0f};
    EXPECT_EQ(sortedUnique(quadEdge(patch, 0)), expected);
}

TEST(TessellatorPattern, CulledPatchesEmitNothing) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    for (Domain d : kDomains) {
        for (Partitioning p : kPartitionings) {
            for (float bad : {0.0f, -0.0f, -3.0f, nan, 1e-40f /* denormal: flushed to zero */}) {
                TessFactors f = uniform(4.0f);
                f.outer[d == Domain::Quad ? 3 : 2] = bad;
                EXPECT_TRUE(Tessellator::tessellate(d, p, f).indices.empty());
                EXPECT_EQ(Tessellator::countTriangles(d, p, f), 0u);
                EXPECT_EQ(Tessellator::countPoints(d, p, f), 0u);
            }
            // Inner levels never cull; a triangle ignores outer[3].
            TessFactors f = uniform(4.0f);
            f.inner = {nan, -1.0f};
            EXPECT_GT(Tessellator::countTriangles(d, p, f), 0u);
        }
    }
    TessFactors f = uniform(4.0f);
    f.outer[3] = 0.0f;
    EXPECT_GT(Tessellator::countTriangles(Domain::Triangle, Partitioning::Integer, f), 0u);
}

TEST(TessellatorPattern, CountsMatchTheBuiltPattern) {
    for (const auto& c : randomCases(3000)) {
        const auto patch = Tessellator::tessellate(c.domain, c.partitioning, c.factors);
        ASSERT_EQ(Tessellator::countTriangles(c.domain, c.partitioning, c.factors), patch.indices.size() / 3);
        ASSERT_EQ(Tessellator::countPoints(c.domain, c.partitioning, c.factors), patch.uv.size());
        ASSERT_EQ(patch.indices.size() % 3, 0u);
    }
}

TEST(TessellatorPattern, PointsStayInTheDomainAndTrianglesAreProper) {
    for (const auto& c : randomCases(1500)) {
        const auto patch = Tessellator::tessellate(c.domain, c.partitioning, c.factors);
        for (const auto& p : patch.uv) {
            ASSERT_GE(p.x, 0.0f);
            ASSERT_GE(p.y, 0.0f);
            ASSERT_LE(p.x, 1.0f);
            ASSERT_LE(p.y, 1.0f);
            if (c.domain == Domain::Triangle) {
                ASSERT_LE(p.x + p.y, 1.0f);
            }
            // Every coordinate is a 16.16 fixed-point value.
            ASSERT_EQ(std::ldexp(p.x, 16), std::floor(std::ldexp(p.x, 16)));
            ASSERT_EQ(std::ldexp(p.y, 16), std::floor(std::ldexp(p.y, 16)));
        }
        std::vector<bool> used(patch.uv.size(), false);
        for (size_t t = 0; t < patch.indices.size(); t += 3) {
            const uint32_t a = patch.indices[t], b = patch.indices[t + 1], e = patch.indices[t + 2];
            ASSERT_LT(std::max({a, b, e}), patch.uv.size());
            ASSERT_TRUE(a != b && b != e && a != e) << "triangle " << t / 3 << " repeats an index";
            used[a] = used[b] = used[e] = true;
            // Winding: Vulkan ccw with the upper-left origin, i.e. clockwise in
            // a v-up plot. Zero-area triangles have no winding.
            ASSERT_LE(signedArea(patch.uv[a], patch.uv[b], patch.uv[e]), 0.0f);
        }
        ASSERT_TRUE(std::all_of(used.begin(), used.end(), [](bool u) { return u; })) << "unreferenced point";
    }
}

TEST(TessellatorPattern, OuterEdgesHaveTheRoundedLevelsPoints) {
    Random rng(7u);
    auto level = [](Random& r) { return r.range(1.0f, 40.0f); };
    for (int i = 0; i < 300; ++i) {
        for (Partitioning p : kPartitionings) {
            TessFactors f{{level(rng), level(rng), level(rng), level(rng)}, {3.0f + level(rng), 3.0f + level(rng)}};
            const auto quad = Tessellator::tessellate(Domain::Quad, p, f);
            for (int e = 0; e < 4; ++e) {
                const auto along = quadEdge(quad, e);
                EXPECT_EQ(along.size(), size_t(segments(p, f.outer[size_t(e)]) + 1)) << e << " " << f.outer[size_t(e)];
                EXPECT_EQ(*std::min_element(along.begin(), along.end()), 0.0f);
                EXPECT_EQ(*std::max_element(along.begin(), along.end()), 1.0f);
            }
            const auto tri = Tessellator::tessellate(Domain::Triangle, p, f);
            size_t onEdge[3] = {0, 0, 0};
            for (const auto& q : tri.uv) {
                onEdge[0] += q.x == 0.0f;
                onEdge[1] += q.y == 0.0f;
                onEdge[2] += q.x + q.y == 1.0f; // exact: both are multiples of 2^-16
            }
            for (int e = 0; e < 3; ++e) EXPECT_EQ(onEdge[e], size_t(segments(p, f.outer[size_t(e)]) + 1)) << e;
        }
    }
}

TEST(TessellatorPattern, SharedEdgesAreWatertight) {
    // Two quads side by side: the left one's u = 1 edge is the right one's
    // u = 0 edge. With the same level there, the points must be identical
    // whatever the other levels, and a triangle edge with that level too.
    Random rng(11u);
    auto level = [](Random& r) { return r.range(1.0f, 64.0f); };
    for (int i = 0; i < 300; ++i) {
        for (Partitioning p : kPartitionings) {
            const float shared = level(rng);
            const TessFactors left{{level(rng), level(rng), shared, level(rng)}, {level(rng), level(rng)}};
            const TessFactors right{{shared, level(rng), level(rng), level(rng)}, {level(rng), level(rng)}};
            const auto a = sortedUnique(quadEdge(Tessellator::tessellate(Domain::Quad, p, left), 2));
            const auto b = sortedUnique(quadEdge(Tessellator::tessellate(Domain::Quad, p, right), 0));
            ASSERT_EQ(a, b) << shared;

            const TessFactors tri{{shared, level(rng), level(rng), 0.0f}, {level(rng), 0.0f}};
            std::vector<float> c;
            for (const auto& q : Tessellator::tessellate(Domain::Triangle, p, tri).uv)
                if (q.x == 0.0f) c.push_back(q.y);
            ASSERT_EQ(a, sortedUnique(c)) << shared;

            // Each edge is symmetric about its midpoint, so the neighbour may
            // run it the other way.
            for (float t : a) ASSERT_TRUE(std::binary_search(a.begin(), a.end(), 1.0f - t)) << shared << " " << t;
        }
    }
}

TEST(TessellatorPattern, ContinuousTopLevelAmplification) {
    // The paper's D3D10-era hardware reaches 411 triangles per superprimitive
    // at level 14.99. D3D11/Vulkan rules give a triangle at 14.99:
    //  - integer and fractional_odd: 15 segments per side, (3 * 15^2 - 1) / 2;
    //  - fractional_even: 16 segments, 3 * 16^2 / 2.
    const uint32_t odd = Tessellator::countTriangles(Domain::Triangle, Partitioning::FractionalOdd, uniform(14.99f));
    const uint32_t integer = Tessellator::countTriangles(Domain::Triangle, Partitioning::Integer, uniform(14.99f));
    const uint32_t even = Tessellator::countTriangles(Domain::Triangle, Partitioning::FractionalEven, uniform(14.99f));
    EXPECT_EQ(odd, 337u);
    EXPECT_EQ(integer, 337u);
    EXPECT_EQ(even, 384u);
    EXPECT_EQ(Tessellator::countTriangles(Domain::Quad, Partitioning::FractionalOdd, uniform(14.99f)), 450u);
    std::printf("triangle patch at 14.99: fractional_odd %u, integer %u, fractional_even %u triangles\n", odd, integer,
                even);
}
