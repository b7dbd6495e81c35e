// The crowd's far creatures in the cascaded shadow maps (docs/LOOKS.md,
// "Cascaded shadow maps", "The cost and auto"): they cast their far mesh
// simplified for depth only (lod::LodPolicy::farCasterTriangles), drawn from
// the far lists' instances through each generation's caster commands
// (GpuCrowd::casterArgs on the vertex-stage backends, the far casters'
// task commands on meshshader). The simplified casters must darken about
// what the far mesh does, and cast at all (an instance count that never
// reached the caster commands would leave the ground lit).
#include "CharacterDemo.h"

#include <gtest/gtest.h>

#include <iostream>
#include <optional>
#include <string>
#include <vector>

using namespace tessera;
using namespace tessera::test;

namespace {

// Every creature in the far tier (no creature is 100,000 pixels across).
std::optional<Rgba8Image> crowdShot(const std::string& backend, const std::string& shadows,
                                    const std::string& casterTriangles, const std::string& name) {
    const std::vector<std::string> args = {
        "--scene",      "crowd",      "--agents", "400", "--meteors", "0",   "--backend",  backend,
        "--tess-max",   "14.99",      "--lod-near", "100000", "--lod-far", "100000", "--width", "320",
        "--height",     "180",        "--frames", "1",   "--shadows", shadows, "--lod-far-caster-triangles",
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

// The far casters' two paths: r2vb's (the vertex-stage casters hulldomain and
// streamout draw too, over their own binning's counts) and meshshader's
// meshlets. The references (no shadows; the far mesh itself as caster) are
// made once, on the first of them the device runs.
TEST(CrowdShadows, FarCreaturesCastTheirSimplifiedMeshesOnEveryCasterPath) {
    std::vector<std::string> backends;
    for (const char* backend : {"r2vb", "meshshader"})
        if (deviceRunsBackend(backend)) backends.push_back(backend);
    if (backends.empty()) GTEST_SKIP() << "the device runs neither r2vb nor meshshader";
    const std::string& first = backends.front();
    const auto lit = crowdShot(first, "none", "0", first + "_none");
    const auto farMesh = crowdShot(first, "cascaded", "0", first + "_far_mesh");
    if (!lit || !farMesh) return;
    const size_t reference = darkened(*farMesh, *lit);
    std::cout << "[crowd shadows] the far mesh's casters darken " << reference << " pixels on " << first << "\n";
    ASSERT_GT(reference, 200u) << "the far creatures cast no cascaded shadow in view";
    for (const std::string& backend : backends) {
        const auto simplified = crowdShot(backend, "cascaded", "96", backend + "_far_casters");
        if (!simplified) continue;
        const size_t count = darkened(*simplified, *lit);
        std::cout << "[crowd shadows] " << backend << ": the simplified casters darken " << count << " pixels\n";
        EXPECT_GT(double(count), 0.8 * double(reference)) << backend << ": the simplified casters lose the shadow";
        EXPECT_LT(double(count), 1.2 * double(reference)) << backend << ": the simplified casters grow the shadow";
    }
}
