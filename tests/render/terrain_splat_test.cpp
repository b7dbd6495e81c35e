// Crater splats: the GPU height map (deformed by a compute pass) and the CPU
// copy (deformed by the same formula for gameplay queries) must agree, touch
// only the samples strictly inside the crater's radius, and give the crater its
// shape: a bowl about `depth` deep at the centre and a raised rim near 0.7 r.
// Meteor showers are deterministic by seed.
#include "DemoProcess.h"

#include "tessera/core/ImageFile.h"
#include "tessera/terrain/HeightMapIO.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

using namespace tessera::test;
using tessera::terrain::HeightField;

namespace {

constexpr float kSpacing = 4.0f;       // metres between samples
constexpr float kHeightRange = 600.0f; // metres spanned by 0..65535

std::filesystem::path outputDir() {
    const std::filesystem::path dir = std::filesystem::path(TESSERA_TEST_OUTPUT_DIR) / "terrain_splat";
    std::filesystem::create_directories(dir);
    return dir;
}

/// The GPU and CPU copies of the height map after a run.
struct HeightDump {
    std::optional<HeightField> gpu;
    std::optional<HeightField> cpu;
    std::string failure; ///< empty on success
};

std::string joined(const std::vector<std::string>& args) {
    std::string text = "tessera-demo";
    for (const auto& a : args) {
        text += ' ';
        text += shellQuote(a);
    }
    return text;
}

/// Runs the demo under the validation layer with `extra` and --dump-heights
/// PREFIX (in the output folder), and loads both dumps.
HeightDump runAndDump(const std::string& name, std::vector<std::string> extra) {
    const std::string prefix = (outputDir() / name).string();
    std::filesystem::remove(prefix + ".gpu.png");
    std::filesystem::remove(prefix + ".cpu.png");
    std::vector<std::string> args = {"--scene", "terrain", "--backend", "hulldomain", "--validation",
                                     "--width", "160",     "--height",  "90"};
    args.insert(args.end(), extra.begin(), extra.end());
    args.insert(args.end(), {"--dump-heights", prefix});
    HeightDump dump;
    const auto run = runDemo(args);
    if (run.exitCode != 0 || run.output.find("validation messages: 0") == std::string::npos) {
        dump.failure = joined(args) + " exited " + std::to_string(run.exitCode) + ":\n" + run.output;
        return dump;
    }
    auto gpu = tessera::terrain::loadHeightMapPng(prefix + ".gpu.png");
    auto cpu = tessera::terrain::loadHeightMapPng(prefix + ".cpu.png");
    if (!gpu) dump.failure += gpu.error().message + "\n";
    if (!cpu) dump.failure += cpu.error().message + "\n";
    if (!dump.failure.empty()) {
        dump.failure = joined(args) + ": " + dump.failure;
        return dump;
    }
    dump.gpu.emplace(std::move(gpu.value()));
    dump.cpu.emplace(std::move(cpu.value()));
    return dump;
}

/// Largest |a - b| over all samples, and how many samples differ at all.
struct Difference {
    int maxAbs = 0;
    size_t differing = 0;
};

Difference compare(const HeightField& a, const HeightField& b) {
    Difference d;
    const auto& sa = a.samples();
    const auto& sb = b.samples();
    for (size_t k = 0; k < sa.size() && k < sb.size(); ++k) {
        const int diff = std::abs(int(sa[k]) - int(sb[k]));
        d.maxAbs = std::max(d.maxAbs, diff);
        d.differing += diff != 0;
    }
    return d;
}

bool sameShape(const HeightField& a, const HeightField& b) {
    return a.width() == b.width() && a.height() == b.height();
}

/// The unsplatted run, shared by every test here (dumping 2048^2 samples twice
/// takes a few seconds on lavapipe).
const HeightDump& plainDump() {
    static const HeightDump dump = runAndDump("nosplat", {"--frames", "2"});
    return dump;
}

/// A meteor shower with a fixed flythrough seed; `name` keeps runs apart.
HeightDump meteorDump(const std::string& name, uint32_t seed, const std::string& screenshot) {
    std::vector<std::string> args = {"--meteors", "10", "--frames", "30", "--seed", std::to_string(seed)};
    if (!screenshot.empty()) args.insert(args.end(), {"--screenshot", screenshot});
    return runAndDump(name, args);
}

} // namespace

TEST(TerrainSplat, UnsplattedCopiesAreIdentical) {
    const auto& plain = plainDump();
    ASSERT_TRUE(plain.failure.empty()) << plain.failure;
    ASSERT_TRUE(sameShape(*plain.gpu, *plain.cpu));
    EXPECT_EQ(plain.gpu->width(), 2048u);
    const auto d = compare(*plain.gpu, *plain.cpu);
    EXPECT_EQ(d.differing, 0u) << "GPU and CPU height maps differ before any crater (max " << d.maxAbs << ")";
}

TEST(TerrainSplat, CraterChangesOnlyInsideItsRadiusOnBothCopies) {
    const float cx = 4000.0f, cz = 4000.0f, radius = 120.0f, depth = 25.0f;
    const auto& plain = plainDump();
    ASSERT_TRUE(plain.failure.empty()) << plain.failure;
    const auto splat = runAndDump("splat", {"--splat", "4000,4000,120,25", "--frames", "2"});
    ASSERT_TRUE(splat.failure.empty()) << splat.failure;
    const HeightField& gpu = *splat.gpu;
    const HeightField& cpu = *splat.cpu;
    const HeightField& before = *plain.cpu;
    ASSERT_TRUE(sameShape(gpu, cpu) && sameShape(cpu, before));

    size_t gpuCpuOff = 0, gpuCpuOffOutside = 0, changedOutside = 0, changedInside = 0;
    int gpuCpuMax = 0;
    bool rimRaised = false;
    std::string firstOutside;
    for (uint32_t j = 0; j < cpu.height(); ++j) {
        for (uint32_t i = 0; i < cpu.width(); ++i) {
            const size_t k = size_t(j) * cpu.width() + i;
            const int g = gpu.samples()[k], c = cpu.samples()[k], b = before.samples()[k];
            const float distance = std::hypot(float(i) * kSpacing - cx, float(j) * kSpacing - cz);
            const bool inside = distance < radius;
            gpuCpuMax = std::max(gpuCpuMax, std::abs(g - c));
            gpuCpuOff += std::abs(g - c) > 1;
            if (!inside) {
                gpuCpuOffOutside += g != c;
                const bool changed = g != b || c != b;
                if (changed && firstOutside.empty()) {
                    std::ostringstream where;
                    where << "(" << i << "," << j << ") at " << distance << " m: before " << b << ", GPU " << g
                          << ", CPU " << c;
                    firstOutside = where.str();
                }
                changedOutside += changed;
            } else {
                changedInside += c != b;
                if (distance > 0.6f * radius && distance < 0.8f * radius && c > b && g > b) rimRaised = true;
            }
        }
    }
    // (a) The copies agree to a rounding step everywhere, exactly outside.
    EXPECT_EQ(gpuCpuOff, 0u) << "GPU and CPU copies differ by more than 1 (max " << gpuCpuMax << ")";
    EXPECT_EQ(gpuCpuOffOutside, 0u) << "GPU and CPU copies differ outside the crater";
    // (b) Nothing at or beyond the radius changed.
    EXPECT_EQ(changedOutside, 0u) << "samples at or beyond the radius changed, first " << firstOutside;
    EXPECT_GT(changedInside, 100u) << "the crater changed almost nothing";
    // (c) The centre is about `depth` lower.
    const uint32_t ci = uint32_t(cx / kSpacing), cj = uint32_t(cz / kSpacing);
    const size_t centre = size_t(cj) * cpu.width() + ci;
    const double expectedDrop = depth / kHeightRange * 65535.0;
    const double drop = double(before.samples()[centre]) - double(cpu.samples()[centre]);
    EXPECT_NEAR(drop, expectedDrop, 0.1 * expectedDrop)
        << "centre sample before " << before.samples()[centre] << ", after " << cpu.samples()[centre];
    const double gpuDrop = double(before.samples()[centre]) - double(gpu.samples()[centre]);
    EXPECT_NEAR(gpuDrop, expectedDrop, 0.1 * expectedDrop);
    // (d) The rim, near 0.7 r, is raised.
    EXPECT_TRUE(rimRaised) << "no sample between 0.6 r and 0.8 r was raised on both copies";
}

TEST(TerrainSplat, MeteorCratersMatchOnGpuAndCpu) {
    const auto& plain = plainDump();
    ASSERT_TRUE(plain.failure.empty()) << plain.failure;
    const auto meteors = meteorDump("meteors_seed3", 3, "");
    ASSERT_TRUE(meteors.failure.empty()) << meteors.failure;
    ASSERT_TRUE(sameShape(*meteors.gpu, *meteors.cpu) && sameShape(*meteors.cpu, *plain.cpu));
    const auto gpuCpu = compare(*meteors.gpu, *meteors.cpu);
    EXPECT_LE(gpuCpu.maxAbs, 1) << gpuCpu.differing << " samples differ between the GPU and CPU copies";
    EXPECT_GT(compare(*meteors.cpu, *plain.cpu).differing, 0u) << "no meteor left a crater on the CPU copy";
    EXPECT_GT(compare(*meteors.gpu, *plain.gpu).differing, 0u) << "no meteor left a crater on the GPU copy";
}

// Determinism: same seed, same craters and the same image; another seed,
// other craters.
TEST(TerrainSplat, MeteorShowerIsDeterministicBySeed) {
    const auto dir = outputDir();
    const std::string shotA = (dir / "meteors_a.png").string(), shotB = (dir / "meteors_b.png").string();
    const auto a = meteorDump("meteors_a", 3, shotA);
    ASSERT_TRUE(a.failure.empty()) << a.failure;
    const auto b = meteorDump("meteors_b", 3, shotB);
    ASSERT_TRUE(b.failure.empty()) << b.failure;
    const auto other = meteorDump("meteors_seed4", 4, "");
    ASSERT_TRUE(other.failure.empty()) << other.failure;

    EXPECT_EQ(a.cpu->samples(), b.cpu->samples()) << "the same seed gave different craters";
    EXPECT_EQ(a.gpu->samples(), b.gpu->samples()) << "the same seed gave different GPU height maps";
    EXPECT_NE(a.cpu->samples(), other.cpu->samples()) << "seeds 3 and 4 gave the same craters";

    auto imageA = tessera::readPng(shotA);
    auto imageB = tessera::readPng(shotB);
    ASSERT_TRUE(imageA) << imageA.error().message;
    ASSERT_TRUE(imageB) << imageB.error().message;
    EXPECT_EQ(imageA.value().width, imageB.value().width);
    EXPECT_EQ(imageA.value().height, imageB.value().height);
    EXPECT_TRUE(imageA.value().pixels == imageB.value().pixels)
        << "the same seed gave different images: " << shotA << " vs " << shotB;
}
