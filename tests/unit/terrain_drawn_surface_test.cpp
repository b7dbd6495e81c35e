// DrawnSurface: the terrain as the backends draw it, evaluated on the CPU.
// Against a brute-force interpolation over every triangle of the patch's
// Tessellator pattern; exact at the pattern's vertices; the control mesh in
// LowRes; and how far it strays from the height field at low levels (the
// reason it exists).

#include "tessera/core/Random.h"
#include "tessera/terrain/DrawnSurface.h"
#include "tessera/terrain/Terrain.h"
#include "tessera/tessellator/Tessellator.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace tessera;
using namespace tessera::terrain;

namespace {

constexpr uint32_t kSize = 129; // 128 spacings of 4 m: 512 m, 4 x 4 patches of 128 m

HeightField hills() {
    std::vector<uint16_t> v(size_t(kSize) * kSize);
    for (uint32_t j = 0; j < kSize; ++j)
        for (uint32_t i = 0; i < kSize; ++i)
            v[size_t(j) * kSize + i] = uint16_t(20000.0 + 12000.0 * std::sin(i * 0.21) * std::cos(j * 0.17));
    return HeightField(kSize, kSize, std::move(v), TerrainScale{4.0f, 600.0f});
}

TessellationSettings screen(float maxLevel) {
    TessellationSettings s;
    s.targetPixels = 8.0f;
    s.maxLevel = maxLevel;
    return s;
}

const TessView kLow{{100.0f, 500.0f, 60.0f}, 540.0f};

float doubleArea(glm::vec2 a, glm::vec2 b, glm::vec2 c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// The drawn height at (x, z) by testing every triangle of the patch's pattern.
float bruteForce(const Terrain& t, const DrawnSurface& s, float x, float z) {
    const glm::vec2 size = t.grid().patchSize();
    const glm::vec2 cell = glm::floor(glm::vec2(x, z) / size);
    const uint32_t patch = uint32_t(cell.y) * t.grid().patchesPerSide() + uint32_t(cell.x);
    const auto f = s.patchFactors(patch);
    const auto pattern = tessellator::Tessellator::tessellate(
        tessellator::Domain::Quad, tessellator::Partitioning::FractionalOdd, {{f[0], f[1], f[2], f[3]}, {f[4], f[5]}});
    const glm::vec2 uv = glm::vec2(x, z) / size - cell;
    for (size_t i = 0; i < pattern.indices.size(); i += 3) {
        const glm::vec2 a = pattern.uv[pattern.indices[i]], b = pattern.uv[pattern.indices[i + 1]],
                        c = pattern.uv[pattern.indices[i + 2]];
        const float area = doubleArea(a, b, c);
        if (area == 0.0f) continue;
        const float wa = doubleArea(uv, b, c) / area, wb = doubleArea(a, uv, c) / area, wc = 1.0f - wa - wb;
        if (std::min({wa, wb, wc}) < -1e-6f) continue;
        auto h = [&](glm::vec2 p) {
            const glm::vec2 xz = (cell + p) * size;
            return t.heightAt(xz.x, xz.y);
        };
        return wa * h(a) + wb * h(b) + wc * h(c);
    }
    ADD_FAILURE() << "no triangle holds " << x << ", " << z;
    return 0.0f;
}

} // namespace

TEST(TerrainDrawnSurface, EqualsTheTessellatedTrianglesEverywhere) {
    Terrain t(hills(), 4);
    DrawnSurface surface(t);
    Random rng(11u);
    for (float maxLevel : {14.99f, 64.0f}) {
        surface.update(screen(maxLevel), kLow, maxLevel);
        for (int k = 0; k < 2000; ++k) {
            const float x = rng.range(0.0f, 511.9f), z = rng.range(0.0f, 511.9f);
            EXPECT_NEAR(surface.heightAt(x, z), bruteForce(t, surface, x, z), 2e-3f) << x << ", " << z;
        }
    }
}

TEST(TerrainDrawnSurface, VerticesAreOnTheHeightFieldLowResIsTheControlMeshHiddenIsTheField) {
    Terrain t(hills(), 4);
    DrawnSurface surface(t);
    // Before any update: the control mesh, two triangles split from
    // (1, 0) to (0, 1) as the lowres draw's indices.
    const glm::vec2 size = t.grid().patchSize();
    const float h00 = t.heightAt(0, 0), h10 = t.heightAt(size.x, 0), h01 = t.heightAt(0, size.y),
                h11 = t.heightAt(size.x, size.y);
    EXPECT_NEAR(surface.heightAt(0.25f * size.x, 0.25f * size.y), 0.5f * h00 + 0.25f * h10 + 0.25f * h01, 1e-3f);
    EXPECT_NEAR(surface.heightAt(0.75f * size.x, 0.75f * size.y), 0.5f * h11 + 0.25f * h10 + 0.25f * h01, 1e-3f);
    // At level 64 (63 segments), every pattern point is on the height field.
    TessellationSettings fine;
    fine.mode = TerrainMode::Continuous;
    fine.continuousLevel = 64.0f;
    surface.update(fine, kLow, 64.0f);
    const auto pattern = tessellator::Tessellator::tessellate(
        tessellator::Domain::Quad, tessellator::Partitioning::FractionalOdd, {{64, 64, 64, 64}, {64, 64}});
    for (const glm::vec2 uv : pattern.uv) {
        const glm::vec2 xz = (glm::vec2(1.0f, 2.0f) + uv) * size;
        EXPECT_NEAR(surface.heightAt(xz.x, xz.y), t.heightAt(xz.x, xz.y), 1e-3f);
    }
    // With the terrain hidden, the height field itself, until the next update.
    TessellationSettings coarse;
    coarse.mode = TerrainMode::Continuous;
    coarse.continuousLevel = 2.0f;
    surface.update(coarse, kLow, 64.0f);
    EXPECT_GT(std::abs(surface.heightAt(200.0f, 90.0f) - t.heightAt(200.0f, 90.0f)), 0.5f);
    surface.useHeightField();
    EXPECT_EQ(surface.heightAt(200.0f, 90.0f), t.heightAt(200.0f, 90.0f));
    surface.update(coarse, kLow, 64.0f);
    EXPECT_NE(surface.heightAt(200.0f, 90.0f), t.heightAt(200.0f, 90.0f));
}

TEST(TerrainDrawnSurface, LowLevelsStrayFromTheHeightFieldAndHighOnesFollowIt) {
    Terrain t(hills(), 4);
    DrawnSurface surface(t);
    auto worst = [&](float level) {
        TessellationSettings s;
        s.mode = TerrainMode::Continuous;
        s.continuousLevel = level;
        surface.update(s, kLow, 64.0f);
        float most = 0.0f;
        for (float z = 2.0f; z < 510.0f; z += 3.7f)
            for (float x = 2.0f; x < 510.0f; x += 3.7f)
                most = std::max(most, std::abs(surface.heightAt(x, z) - t.heightAt(x, z)));
        return most;
    };
    // Steep hills (110 m high, 120 m from crest to crest): a 128 m patch at
    // level 3 cuts across them by tens of metres (measured 80.7), at 14.99
    // (9 m segments) by metres (4.8), at 64 (2 m segments) by under one (0.9).
    const float coarse = worst(3.0f), emulated = worst(14.99f), fine = worst(64.0f);
    std::printf("worst: level 3 %.2f m, 14.99 %.2f m, 64 %.2f m\n", coarse, emulated, fine);
    EXPECT_GT(coarse, 10.0f);
    EXPECT_GT(coarse, 4.0f * emulated);
    EXPECT_GT(emulated, 4.0f * fine);
}
