// The displacement baker against surfaces whose answer is known: a cube cage
// (six UV charts, every cube edge a seam) and a sculpt that is the cage's own
// interpolating planar subdivision displaced by an analytic field along the
// same interpolated normal the renderer uses.

#include "BakeTestMeshes.h"
#include "creature/DisplacementBaker.h"
#include "tessera/assets/GltfLoader.h"
#include "tessera/core/Random.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

using namespace tessera;
using namespace tessera::creature;
using namespace tessera::creature::baketest;

namespace {

struct CubeCase {
    CageMesh cage = makeCubeCage(6);
    SculptMesh sculpt = subdivideCage(cage, 12, field);
};

const CubeCase& cubeCase() {
    static const CubeCase c;
    return c;
}

BakeResult bakeOk(const CageMesh& cage, const SculptMesh& sculpt, const BakeOptions& options) {
    Result<BakeResult> r = bakeDisplacement(cage, sculpt, options);
    EXPECT_TRUE(r.ok()) << (r.ok() ? "" : r.error().message);
    return r.ok() ? std::move(r).value() : BakeResult{};
}

BakeOptions cubeOptions() {
    BakeOptions o;
    o.resolution = 256;
    o.outerEnvelope = o.innerEnvelope = 0.1f;
    o.threads = 2;
    return o;
}

} // namespace

TEST(DisplacementBaker, ReproducesAnalyticFieldOnCube) {
    BakeResult r = bakeOk(cubeCase().cage, cubeCase().sculpt, cubeOptions());
    ASSERT_EQ(r.displacement.image.format, character::TextureFormat::R16);
    ASSERT_EQ(r.displacement.image.width, 256u);
    EXPECT_EQ(r.stats.misses, 0u);
    EXPECT_GT(r.stats.texelsCovered, 30000u);
    EXPECT_EQ(r.displacement.bias, r.stats.minDisplacement);
    EXPECT_EQ(r.displacement.scale, r.stats.maxDisplacement - r.stats.minDisplacement);
    EXPECT_LT(r.stats.minDisplacement, -0.015f);
    EXPECT_GT(r.stats.maxDisplacement, 0.015f);

    const std::vector<float> texels = decode(r.displacement);
    float worst = 0.0f;
    int samples = 0;
    for (const CubeFace& f : kFaces) {
        for (int j = 0; j <= 40; ++j) {
            for (int i = 0; i <= 40; ++i) {  // includes the chart borders, seams and corners
                float s = i / 40.0f, t = j / 40.0f;
                glm::vec3 p = 0.5f * f.n + (s - 0.5f) * f.u + (t - 0.5f) * f.v;
                worst = std::max(worst, std::fabs(fetch(texels, 256, atlasUv(f, s, t)) - field(p)));
                ++samples;
            }
        }
    }
    std::printf("analytic field: %d fetches, worst error %.3g (field amplitude 0.03)\n", samples, worst);
    EXPECT_LT(worst, 1.5e-4f);
}

TEST(DisplacementBaker, SeamFixMakesBothSidesAgree) {
    BakeResult r = bakeOk(cubeCase().cage, cubeCase().sculpt, cubeOptions());
    EXPECT_EQ(r.stats.seamEdges, 12u * 6u);  // every cube edge, 6 cage edges each
    EXPECT_GT(r.stats.seamTexelsFixed, 0u);
    std::printf("seam mismatch before %.3g after %.3g, %llu texels fixed, %llu seam vertex pairs\n",
                r.stats.seamMismatchBefore, r.stats.seamMismatchAfter,
                static_cast<unsigned long long>(r.stats.seamTexelsFixed),
                static_cast<unsigned long long>(r.stats.seamVertices));
    // Quantisation alone allows ~1e-6 (scale 0.05 / 65535); two bilinear
    // fetches along one edge can rarely agree exactly everywhere.
    EXPECT_LT(r.stats.seamMismatchAfter, 1e-5f);
    EXPECT_LT(r.stats.seamMismatchAfter * 20.0f, r.stats.seamMismatchBefore);
}

TEST(DisplacementBaker, NarrowEnvelopeMissesAreCountedAndFilled) {
    BakeOptions o = cubeOptions();
    o.outerEnvelope = o.innerEnvelope = 0.005f;
    BakeResult r = bakeOk(cubeCase().cage, cubeCase().sculpt, o);
    EXPECT_GT(r.stats.misses, 1000u);
    // Filled from hits: nothing outside what the envelope could see (the
    // seam solve may nudge a texel by its own small residual).
    EXPECT_GE(r.stats.minDisplacement, -0.0052f);
    EXPECT_LE(r.stats.maxDisplacement, 0.0052f);
}

TEST(DisplacementBaker, MissesCountedExactly) {
    // The sculpt covers only x <= 0.5: texel columns 32..63 of 64 see nothing.
    CageMesh cage = makePlaneCage(4);
    SculptMesh sculpt = makeHeightSculpt(-0.1f, 0.5f, -0.1f, 1.1f, 8, [](float, float) { return 0.02f; });
    BakeOptions o;
    o.resolution = 64;
    o.threads = 2;
    BakeResult r = bakeOk(cage, sculpt, o);
    EXPECT_EQ(r.stats.texelsCovered, 64u * 64u);
    EXPECT_EQ(r.stats.misses, 32u * 64u);
    ASSERT_EQ(r.stats.missesPerTriangle.size(), cage.triangleCount());
    // Cage columns 2 and 3 (x >= 0.5) hold every miss: 16 triangles of 32.
    uint64_t total = 0;
    for (uint32_t t = 0; t < cage.triangleCount(); ++t) {
        uint32_t column = (t / 2) % 4;
        EXPECT_EQ(r.stats.missesPerTriangle[t] > 0, column >= 2) << "triangle " << t;
        total += r.stats.missesPerTriangle[t];
    }
    EXPECT_EQ(total, r.stats.misses);
    EXPECT_EQ(r.stats.seamEdges, 0u);
    EXPECT_NEAR(r.displacement.bias, 0.02f, 1e-6f);  // misses filled with the neighbours' 0.02
    EXPECT_LT(r.displacement.scale, 1e-6f);

    // Entirely outside the envelope: every texel misses.
    SculptMesh far = makeHeightSculpt(-0.1f, 1.1f, -0.1f, 1.1f, 4, [](float, float) { return 0.2f; });
    EXPECT_EQ(bakeOk(cage, far, o).stats.misses, 64u * 64u);
}

TEST(DisplacementBaker, FlatSculptGivesUpNormals) {
    CageMesh cage = makePlaneCage(3);
    SculptMesh flat = makeHeightSculpt(-0.1f, 1.1f, -0.1f, 1.1f, 10, [](float, float) { return 0.0f; });
    BakeOptions o;
    o.resolution = 32;
    o.normalResolution = 16;
    BakeResult r = bakeOk(cage, flat, o);
    ASSERT_EQ(r.normalMap.width, 16u);
    ASSERT_EQ(r.normalMap.bytes.size(), 16u * 16u * 4u);
    for (size_t i = 0; i < r.normalMap.bytes.size(); i += 4) {
        ASSERT_EQ(r.normalMap.bytes[i], 128);
        ASSERT_EQ(r.normalMap.bytes[i + 1], 128);
        ASSERT_EQ(r.normalMap.bytes[i + 2], 255);
        ASSERT_EQ(r.normalMap.bytes[i + 3], 255);
    }
    EXPECT_EQ(r.displacement.scale, 0.0f);

    // A slope z = 0.1 x tilts the normal towards -x in the (T = +x) tangent frame.
    SculptMesh slope = makeHeightSculpt(-0.1f, 1.1f, -0.1f, 1.1f, 10, [](float x, float) { return 0.1f * x; });
    BakeResult s = bakeOk(cage, slope, o);
    glm::vec3 expected = glm::normalize(glm::vec3(-0.1f, 0.0f, 1.0f)) * 0.5f + 0.5f;
    size_t centre = (8 * 16 + 8) * 4;
    EXPECT_NEAR(s.normalMap.bytes[centre], expected.x * 255.0f, 1.0f);
    EXPECT_NEAR(s.normalMap.bytes[centre + 1], 128.0f, 1.0f);
    EXPECT_NEAR(s.normalMap.bytes[centre + 2], expected.z * 255.0f, 1.0f);
}

TEST(DisplacementBaker, GutterPadsChartsWithoutTouchingThem) {
    // One chart in the lower-left quarter of the map.
    CageMesh cage = makePlaneCage(4);
    for (CageVertex& v : cage.vertices) v.uv *= 0.5f;
    SculptMesh sculpt = makeHeightSculpt(-0.1f, 1.1f, -0.1f, 1.1f, 40,
                                         [](float x, float y) { return 0.01f * std::sin(6 * x) * std::cos(5 * y); });
    BakeOptions o;
    o.resolution = 64;
    o.gutter = 0;
    BakeResult bare = bakeOk(cage, sculpt, o);
    o.gutter = 4;
    std::vector<float> progress;
    Result<BakeResult> padded = bakeDisplacement(cage, sculpt, o, [&](float f) { progress.push_back(f); });
    ASSERT_TRUE(padded.ok());
    ASSERT_FALSE(progress.empty());
    EXPECT_TRUE(std::is_sorted(progress.begin(), progress.end()));
    EXPECT_EQ(progress.back(), 1.0f);

    std::vector<float> a = decode(bare.displacement), b = decode(padded->displacement);
    // Chart texels (x, y < 33: the 32 covered plus the dilated ring) are identical.
    for (uint32_t y = 0; y < 33; ++y) {
        for (uint32_t x = 0; x < 33; ++x) ASSERT_NEAR(a[y * 64 + x], b[y * 64 + x], 1e-6f) << x << "," << y;
    }
    // The gutter continues the chart's border; beyond it lies the charts' mean.
    for (uint32_t y = 0; y < 32; ++y) {
        EXPECT_NEAR(b[y * 64 + 36], b[y * 64 + 32], 2e-4f) << y;
        EXPECT_NEAR(b[y * 64 + 40], a[y * 64 + 40], 1e-6f);
    }
}

TEST(DisplacementBaker, SameBytesForAnyThreadCount) {
    BakeOptions o = cubeOptions();
    o.resolution = 128;
    o.threads = 1;
    BakeResult a = bakeOk(cubeCase().cage, cubeCase().sculpt, o);
    o.threads = 2;
    BakeResult b = bakeOk(cubeCase().cage, cubeCase().sculpt, o);
    EXPECT_EQ(a.displacement.image.bytes, b.displacement.image.bytes);
    EXPECT_EQ(a.normalMap.bytes, b.normalMap.bytes);
    EXPECT_EQ(a.displacement.scale, b.displacement.scale);
    EXPECT_EQ(a.displacement.bias, b.displacement.bias);
}

TEST(DisplacementBaker, RejectsBadInput) {
    CageMesh cage = makePlaneCage(1);
    SculptMesh sculpt = makeHeightSculpt(0, 1, 0, 1, 1, [](float, float) { return 0.0f; });
    auto expectError = [](const Result<BakeResult>& r, const char* what) {
        ASSERT_FALSE(r.ok()) << what;
        EXPECT_EQ(r.error().message.rfind("bakeDisplacement: ", 0), 0u) << r.error().message;
        EXPECT_EQ(r.error().message.find('\n'), std::string::npos);
    };
    BakeOptions o;
    o.resolution = 0;
    expectError(bakeDisplacement(cage, sculpt, o), "resolution 0");
    o.resolution = 4096;
    expectError(bakeDisplacement(cage, sculpt, o), "resolution 4096");
    o.resolution = 16;
    o.normalResolution = 4096;
    expectError(bakeDisplacement(cage, sculpt, o), "normal resolution");
    o.normalResolution = 0;
    o.outerEnvelope = 0.0f;
    expectError(bakeDisplacement(cage, sculpt, o), "zero envelope");
    o.outerEnvelope = 0.1f;
    o.innerEnvelope = std::nanf("");
    expectError(bakeDisplacement(cage, sculpt, o), "NaN envelope");
    o.innerEnvelope = 0.1f;
    CageMesh noUv = cage;
    for (CageVertex& v : noUv.vertices) v.uv = {0.0f, 0.0f};
    expectError(bakeDisplacement(noUv, sculpt, o), "no UVs");
    CageMesh badIndex = cage;
    badIndex.indices[0] = 99;
    expectError(bakeDisplacement(badIndex, sculpt, o), "cage index");
    expectError(bakeDisplacement(cage, SculptMesh{}, o), "empty sculpt");
    EXPECT_TRUE(bakeDisplacement(cage, sculpt, o).ok());
}

namespace {

const std::string kGltfDir = std::string(TESSERA_SOURCE_DIR) + "/../shared/testdata/gltf/";

} // namespace

TEST(DisplacementBaker, RealCharacterCesiumMan) {
    // A real cage: Khronos' CesiumMan (4.7K triangles, its own UV atlas and
    // seams), displaced by a known field along its interpolated normals.
    Result<character::CharacterAsset> asset = assets::loadCharacter(kGltfDir + "CesiumMan/glTF-Binary/CesiumMan.glb");
    ASSERT_TRUE(asset.ok()) << asset.error().message;
    const CageMesh& cage = asset->cage;
    auto wave = [](const glm::vec3& p) {
        return 0.01f * std::sin(20.0f * p.x + 1.0f) * std::cos(15.0f * p.y) * std::cos(9.0f * p.z);
    };
    BakeOptions o;
    o.resolution = 256;
    o.innerEnvelope = o.outerEnvelope = 0.03f;
    o.threads = 2;
    BakeResult r = bakeOk(cage, subdivideCage(cage, 4, wave), o);
    EXPECT_EQ(r.stats.misses, 0u);
    EXPECT_GT(r.stats.seamEdges, 100u);
    EXPECT_LT(r.stats.seamMismatchAfter, 5e-5f);
    EXPECT_LT(r.stats.seamMismatchAfter * 5.0f, r.stats.seamMismatchBefore);

    // Fetch at random surface points exactly as the renderer does.
    const std::vector<float> texels = decode(r.displacement);
    Random rng(3);
    std::vector<float> errors;
    for (int i = 0; i < 5000; ++i) {
        uint32_t t = rng.below(cage.triangleCount());
        float b1 = rng.nextFloat(), b2 = rng.nextFloat();
        if (b1 + b2 > 1.0f) {
            b1 = 1.0f - b1;
            b2 = 1.0f - b2;
        }
        const CageVertex* v[3] = {&cage.vertices[cage.indices[3 * t]], &cage.vertices[cage.indices[3 * t + 1]],
                                  &cage.vertices[cage.indices[3 * t + 2]]};
        float b0 = 1.0f - b1 - b2;
        glm::vec3 p = b0 * v[0]->position + b1 * v[1]->position + b2 * v[2]->position;
        glm::vec2 uv = b0 * v[0]->uv + b1 * v[1]->uv + b2 * v[2]->uv;
        errors.push_back(std::fabs(fetch(texels, 256, uv) - wave(p)));
    }
    std::sort(errors.begin(), errors.end());
    std::printf("CesiumMan: seams %llu, mismatch %.3g -> %.3g; field error p50 %.3g p99 %.3g max %.3g\n",
                static_cast<unsigned long long>(r.stats.seamEdges), r.stats.seamMismatchBefore,
                r.stats.seamMismatchAfter, errors[2500], errors[4950], errors.back());
    EXPECT_LT(errors[2500], 3e-5f);  // amplitude 0.01
    EXPECT_LT(errors[4950], 3e-4f);
    EXPECT_LT(errors.back(), 1.5e-3f);
}

TEST(DisplacementBaker, RejectsTiledUvsOfARealModel) {
    // BoxTextured repeats its texture (UVs up to 6): no place for a unique bake.
    Result<character::CharacterAsset> asset = assets::loadCharacter(kGltfDir + "BoxTextured/glTF-Binary/BoxTextured.glb");
    ASSERT_TRUE(asset.ok()) << asset.error().message;
    SculptMesh sculpt = subdivideCage(asset->cage, 1, [](const glm::vec3&) { return 0.0f; });
    Result<BakeResult> r = bakeDisplacement(asset->cage, sculpt, BakeOptions{});
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().message.find("outside [0, 1]"), std::string::npos) << r.error().message;
}

// The performance figure for the report: a 4.8K-triangle cage, a 1.39M-triangle
// sculpt, 2048^2. Run with --gtest_also_run_disabled_tests.
TEST(DisplacementBaker, DISABLED_Benchmark2048) {
    CageMesh cage = makeCubeCage(20);
    SculptMesh sculpt = subdivideCage(cage, 17, field);
    BakeOptions o;
    o.resolution = 2048;
    o.outerEnvelope = o.innerEnvelope = 0.1f;
    o.threads = 2;
    auto start = std::chrono::steady_clock::now();
    auto since = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
    double bvhSeconds = 0.0, raySeconds = 0.0;
    Result<BakeResult> baked = bakeDisplacement(cage, sculpt, o, [&](float f) {
        if (f >= 0.1f && bvhSeconds == 0.0) bvhSeconds = since();
        if (f >= 0.9f && raySeconds == 0.0) raySeconds = since();
    });
    double seconds = since();
    ASSERT_TRUE(baked.ok());
    const BakeResult& r = baked.value();
    std::printf("BVH + sculpt normals %.2f s, rays done at %.2f s\n", bvhSeconds, raySeconds);
    std::printf("cage %u tris, sculpt %u tris, 2048^2: %.2f s; covered %llu dilated %llu misses %llu; seams %llu, "
                "mismatch %.3g -> %.3g\n",
                cage.triangleCount(), sculpt.triangleCount(), seconds,
                static_cast<unsigned long long>(r.stats.texelsCovered),
                static_cast<unsigned long long>(r.stats.texelsDilated),
                static_cast<unsigned long long>(r.stats.misses), static_cast<unsigned long long>(r.stats.seamEdges),
                r.stats.seamMismatchBefore, r.stats.seamMismatchAfter);
}
