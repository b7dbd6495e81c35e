// The crowd's middle and far creatures in the cascaded shadow maps
// (docs/LOOKS.md, "Cascaded shadow maps", "The middle and far tiers'
// casters"): both cast from the far mesh's vertices, the middle tier its
// triangles, the far tier the far mesh simplified for depth only
// (lod::LodPolicy::farCasterTriangles), drawn from each list's instances
// through each generation's caster commands (GpuCrowd::casterArgs on the
// vertex-stage backends, the casters' task commands on meshshader). The
// simplified casters must darken about what the far mesh does, and both
// must cast at all (an instance count that never reached the caster
// commands would leave the ground lit).
#include "CharacterDemo.h"

#include <gtest/gtest.h>

#include <iostream>
#include <optional>
#include <string>
#include <vector>

using namespace tessera;
using namespace tessera::test;

namespace {

// Creatures 20 pixels across and more in the middle tier, the rest in the
// far tier; the far tier's casters are the far mesh simplified to
// `casterTriangles` (0: the far mesh).
std::optional<Rgba8Image> crowdShot(const std::string& backend, const std::string& shadows,
                                    const std::string& casterTriangles, const std::string& name) {
    const std::vector<std::string> args = {
        "--scene",    "crowd",  "--agents",  "400", "--meteors", "0",     "--backend",  backend,
        "--tess-max", "14.99",  "--lod-near", "100000", "--lod-far", "20", "--width",    "320",
        "--height",   "180",    "--frames",  "1",   "--shadows", shadows, "--lod-far-caster-triangles",
        casterTriangles};
    const DemoShot s = runDemoShot(args, testOutputDir("crowd_shadows") / (name + ".png"));
    EXPECT_EQ(s.result.exitCode, 0) << s.command << "\n" << s.result.output;
    EXPECT_TRUE(validationClean(s.result)) << s.command << "\n" << s.result.output;
    EXPECT_TRUE(s.image) << s.command << ": " << s.readError;
    return s.image;
}

double luminance(const Rgba8Image& image, size_t i) {
    const uint8_t* p = &image.pixels[i * 4];
    return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
}

/// Pixels `shadowed` keeps less than three quarters of the light of `lit`
/// (the same frame without character shadows): the ground and the
/// creatures the far casters darken.
size_t darkened(const Rgba8Image& shadowed, const Rgba8Image& lit) {
    size_t count = 0;
    for (size_t i = 0; i < size_t(lit.width) * lit.height; ++i)
        if (luminance(shadowed, i) < 0.75 * luminance(lit, i)) ++count;
    return count;
}

} // namespace

// The casters' two paths: r2vb's (the vertex-stage casters hulldomain and
// streamout draw too, over their own binning's counts) and meshshader's
// meshlets. The references (no shadows; the far tier casting the whole far
// mesh) are made once, on the first of them the device runs. With far
// casters of two triangles (as good as none) the frame keeps 81% of the
// reference's darkened pixels (822 of 1,019), the middle tier's casters
// being the rest: the bar, 90% to 110%, fails without either.
TEST(CrowdShadows, MiddleAndFarCreaturesCastFromTheFarMeshOnEveryCasterPath) {
    std::vector<std::string> backends;
    for (const char* backend : {"r2vb", "meshshader"})
        if (deviceRunsBackend(backend)) backends.push_back(backend);
    if (backends.empty()) GTEST_SKIP() << "the device runs neither r2vb nor meshshader";
    const std::string& first = backends.front();
    const auto lit = crowdShot(first, "none", "0", first + "_none");
    const auto farMesh = crowdShot(first, "cascaded", "0", first + "_far_mesh");
    if (!lit || !farMesh) return;
    const size_t reference = darkened(*farMesh, *lit);
    std::cout << "[crowd shadows] casting the far mesh darkens " << reference << " pixels on " << first << "\n";
    ASSERT_GT(reference, 200u) << "the creatures cast no cascaded shadow in view";
    for (const std::string& backend : backends) {
        const auto simplified = crowdShot(backend, "cascaded", "96", backend + "_casters");
        if (!simplified) continue;
        const size_t count = darkened(*simplified, *lit);
        std::cout << "[crowd shadows] " << backend << ": the casters darken " << count << " pixels\n";
        EXPECT_GT(double(count), 0.9 * double(reference)) << backend << ": the casters lose the shadow";
        EXPECT_LT(double(count), 1.1 * double(reference)) << backend << ": the casters grow the shadow";
    }
}
