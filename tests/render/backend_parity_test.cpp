// Backend parity: hulldomain (hardware tessellation), r2vb and streamout (the
// emulated D3D11 tessellator) and meshshader (the patterns from task and mesh
// shaders) must draw the same tessellated terrain when the levels stay within
// the emulated range (--tess-max 14.99, continuous levels up to 14.99), and
// meshshader also above it, up to 64. Each case renders one fixed view on
// every backend it names under the validation layer and checks, against
// hulldomain:
//  - the triangles of the tessellated pass ("terrain.continuous" or
//    "terrain.adaptive"): the primitives generated for the clipper (the
//    pipeline statistics' clipping invocations, or the mesh primitives
//    generated where a device counts no clipping for mesh pipelines) of the
//    median frame, from --benchmark, must be equal;
//  - the images must match within kParityTolerance; a diff image
//    (test-output/backend_parity/<case>.<backend>.diff.png) is written on a
//    mismatch.
// The other per-pass statistics (vertex, tessellation-evaluation and
// geometry-shader invocations, clipping primitives, fragment invocations) are
// printed for every backend but not compared: each technique reaches the same
// triangles through different stages.
#include "DemoProcess.h"
#include "TestFiles.h"
#include "ImageCompare.h"
#include "JsonFile.h"

#include "tessera/core/ImageFile.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

using namespace tessera;
using namespace tessera::test;

namespace {

const char* const kReference = "hulldomain";
const std::vector<std::string> kCompared = {"r2vb", "streamout", "meshshader"};

// The golden images' view across a valley towards the mountains: patches from
// a few hundred metres to the horizon, so the adaptive levels span 1 to the
// 14.99 cap, and the craters below lie in the middle distance.
const std::vector<std::string> kView = {"--camera", "1800,900,6800,-30,-16", "--width", "320", "--height", "180"};

// The same triangles give all but a few pixels bit for bit. Measured over
// every case at 320x180 (57,600 pixels):
//  - lavapipe: at most 110 pixels differ at all, scattered, almost all by
//    1/255; at most 2 by more than 8/255 (one by 17); mean difference at
//    most 0.0011. The fragment-shader invocations are equal there too, so
//    this is most likely rounding in the interpolated attributes (the same
//    triangle from the evaluation stage and from the emulated draw), not
//    coverage;
//  - H100: at most 8 pixels differ at all, at most 1 by more than 8 (by 45);
//    mean at most 0.0012.
// The bound allows 0.05% of the pixels (28) to differ by more than 8/255 and
// a mean difference of 0.05, 14x and 40x the worst measured. A changed
// fractional level (3.7 to 3.9, the same triangle count) gives 3.9% and 1.16
// (DetectsAChangedLevel), far outside it.
const ImageTolerance kParityTolerance{8, 0.0005, 0.05};

struct ParityCase {
    std::string name;
    std::string pass; ///< the tessellated pass whose triangles are compared
    std::vector<std::string> args;
    std::vector<std::string> backends = kCompared; ///< compared with hulldomain
};

// gtest prints a parameter's bytes unless told otherwise; the name says it all.
void PrintTo(const ParityCase& c, std::ostream* os) {
    *os << c.name;
}

std::vector<ParityCase> parityCases() {
    const std::vector<std::string> adaptive = {"--terrain-mode", "adaptive", "--tess-max", "14.99"};
    auto withAdaptive = [&](std::vector<std::string> extra) {
        std::vector<std::string> args = adaptive;
        args.insert(args.end(), extra.begin(), extra.end());
        return args;
    };
    // The targets are set so that each metric spans level 1 to the cap in this
    // view (the cap changes the triangle count in every adaptive case but
    // detail's, which peaks near 12): fractional levels, odd/even transitions
    // and clamping all occur.
    return {
        {"continuous_l3_7", "terrain.continuous", {"--terrain-mode", "continuous", "--tess-level", "3.7"}},
        {"continuous_l14_99", "terrain.continuous", {"--terrain-mode", "continuous", "--tess-level", "14.99"}},
        {"adaptive_screen", "terrain.adaptive", withAdaptive({"--tess-metric", "screen", "--tess-target", "3"})},
        {"adaptive_distance", "terrain.adaptive",
         withAdaptive({"--tess-metric", "distance", "--tess-distance", "2500"})},
        {"adaptive_silhouette", "terrain.adaptive",
         withAdaptive({"--tess-metric", "silhouette", "--tess-target", "2.5"})},
        {"adaptive_detail", "terrain.adaptive", withAdaptive({"--tess-metric", "detail", "--tess-target", "0.25"})},
        // Craters in view, stamped before the first frame: they move the
        // surface, and the detail metric reads the detail errors the CPU
        // recomputed around them (the screen metric's levels would not change).
        {"craters_adaptive_detail", "terrain.adaptive",
         withAdaptive({"--tess-metric", "detail", "--tess-target", "0.25", "--splat", "2800,5000,200", "--splat",
                       "2300,5900,120"})},
        {"craters_continuous_l7_5",
         "terrain.continuous",
         {"--terrain-mode", "continuous", "--tess-level", "7.5", "--splat", "2800,5000,200", "--splat",
          "2300,5900,120"}},
        // Above the emulated range: only the mesh-shader patterns go there.
        {"continuous_l27_3", "terrain.continuous", {"--terrain-mode", "continuous", "--tess-level", "27.3"}, {"meshshader"}},
        {"adaptive_screen_l64",
         "terrain.adaptive",
         {"--terrain-mode", "adaptive", "--tess-max", "64", "--tess-metric", "screen", "--tess-target", "1.5"},
         {"meshshader"}},
    };
}

std::string commandLine(const std::vector<std::string>& args) {
    std::string text = "tessera-demo";
    for (const auto& a : args) {
        text += ' ';
        text += shellQuote(a);
    }
    return text;
}

/// Pipeline statistics of one pass in the median frame.
struct PassStats {
    uint64_t clippingInvocations = 0;
    uint64_t meshPrimitivesGenerated = 0;
    /// Triangles generated for the clipper (profiler::generatedPrimitivesOf).
    uint64_t generated() const { return clippingInvocations != 0 ? clippingInvocations : meshPrimitivesGenerated; }
    uint64_t clippingPrimitives = 0;
    uint64_t vertexShaderInvocations = 0;
    uint64_t tessEvaluationInvocations = 0;
    uint64_t geometryShaderInvocations = 0;
    uint64_t fragmentShaderInvocations = 0;
};

struct BackendRun {
    std::string backend;
    std::string command;
    ProcessResult result;
    std::string screenshot;
    std::optional<PassStats> stats; ///< of the case's tessellated pass
    std::string passes;             ///< every pass the report lists, for messages
    std::string error;              ///< why stats are missing
};

/// Finds `passName` in the benchmark report at `path`.
void readStats(const std::string& path, const std::string& passName, BackendRun& run) {
    nlohmann::json report;
    std::string error;
    if (!readJsonFile(path, report, error)) {
        run.error = path + ": " + error;
        return;
    }
    const nlohmann::json* passes = memberOf(report, "passes");
    if (!passes || !passes->is_array()) {
        run.error = path + ": no \"passes\" list";
        return;
    }
    for (const nlohmann::json& pass : *passes) {
        const std::string name = stringAt(pass, "name").value_or("?");
        run.passes += (run.passes.empty() ? "" : ", ") + name;
        if (name != passName) continue;
        const nlohmann::json* s = memberOf(pass, "statsMedianFrame");
        if (!s || !s->is_object()) {
            run.error = path + ": pass " + passName + " has no pipeline statistics";
            return;
        }
        auto count = [&](const char* key) { return static_cast<uint64_t>(numberAt(*s, key).value_or(0.0)); };
        PassStats stats;
        stats.clippingInvocations = count("clippingInvocations");
        stats.meshPrimitivesGenerated = count("meshPrimitivesGenerated");
        stats.clippingPrimitives = count("clippingPrimitives");
        stats.vertexShaderInvocations = count("vertexShaderInvocations");
        stats.tessEvaluationInvocations = count("tessEvaluationInvocations");
        stats.geometryShaderInvocations = count("geometryShaderInvocations");
        stats.fragmentShaderInvocations = count("fragmentShaderInvocations");
        run.stats = stats;
    }
    if (!run.stats && run.error.empty()) run.error = path + ": no pass named " + passName;
}

BackendRun runBackend(const ParityCase& c, const std::string& backend) {
    const auto dir = testOutputDir("backend_parity");
    const std::string stem = (dir / (c.name + "." + backend)).string();
    BackendRun run;
    run.backend = backend;
    run.screenshot = stem + ".png";
    const std::string bench = stem + ".json";
    std::filesystem::remove(run.screenshot);
    std::filesystem::remove(bench);
    std::vector<std::string> args = {"--scene", "terrain", "--backend",   backend, "--validation", "--frames",    "2",
                                     "--benchmark", bench,   "--screenshot", run.screenshot};
    args.insert(args.end(), kView.begin(), kView.end());
    args.insert(args.end(), c.args.begin(), c.args.end());
    run.command = commandLine(args);
    run.result = runDemo(args);
    if (run.result.exitCode == 0) readStats(bench, c.pass, run);
    return run;
}

std::string describe(const BackendRun& run) {
    if (!run.stats) return run.backend + ": no statistics";
    const PassStats& s = *run.stats;
    std::ostringstream out;
    out << run.backend << ": clipping invocations " << s.clippingInvocations << ", mesh primitives "
        << s.meshPrimitivesGenerated << ", clipping primitives "
        << s.clippingPrimitives << ", VS " << s.vertexShaderInvocations << ", TES " << s.tessEvaluationInvocations
        << ", GS " << s.geometryShaderInvocations << ", FS " << s.fragmentShaderInvocations;
    return out.str();
}

/// Differences beyond what ImageComparison reports: how many pixels differ at
/// all and by how much at most, so the log shows the real figures even when
/// they are within the tolerance.
struct PixelDelta {
    size_t anyDifference = 0;
    int maxChannel = 0;
};

PixelDelta pixelDelta(const Rgba8Image& a, const Rgba8Image& b) {
    PixelDelta d;
    if (a.width != b.width || a.height != b.height) return d;
    for (size_t p = 0; p + 3 < a.pixels.size(); p += 4) {
        int worst = 0;
        for (int ch = 0; ch < 3; ++ch) worst = std::max(worst, std::abs(int(a.pixels[p + ch]) - int(b.pixels[p + ch])));
        d.anyDifference += worst > 0;
        d.maxChannel = std::max(d.maxChannel, worst);
    }
    return d;
}

/// "the device cannot run it" is not a parity failure: the test skips that backend.
bool deviceCannotRun(const BackendRun& run) {
    return tessera::test::deviceCannotRun(run.result);
}

class BackendParity : public ::testing::TestWithParam<ParityCase> {};

} // namespace

TEST_P(BackendParity, TrianglesAndImagesMatchHulldomain) {
    const ParityCase& c = GetParam();
    const BackendRun reference = runBackend(c, kReference);
    if (deviceCannotRun(reference)) GTEST_SKIP() << reference.command << "\n" << reference.result.output;
    ASSERT_EQ(reference.result.exitCode, 0) << reference.command << "\n" << reference.result.output;
    EXPECT_NE(reference.result.output.find("validation messages: 0"), std::string::npos) << reference.command << "\n"
                                                                                         << reference.result.output;
    ASSERT_TRUE(reference.stats) << reference.command << ": " << reference.error << " (passes: " << reference.passes
                                 << ")";
    ASSERT_GT(reference.stats->clippingInvocations, 0u) << reference.command;
    auto expected = readPng(reference.screenshot);
    ASSERT_TRUE(expected.ok()) << reference.screenshot << ": " << expected.error().message;
    std::cout << "[parity] " << c.name << " " << describe(reference) << "\n";

    for (const std::string& backend : c.backends) {
        SCOPED_TRACE(backend);
        const BackendRun run = runBackend(c, backend);
        if (deviceCannotRun(run)) {
            std::cout << "[parity] " << c.name << " " << backend << ": skipped, the device cannot run it\n";
            continue;
        }
        EXPECT_EQ(run.result.exitCode, 0) << run.command << "\n" << run.result.output;
        if (run.result.exitCode != 0) continue;
        EXPECT_NE(run.result.output.find("validation messages: 0"), std::string::npos) << run.command << "\n"
                                                                                       << run.result.output;
        EXPECT_TRUE(run.stats) << run.command << ": " << run.error << " (passes: " << run.passes << ")";
        if (run.stats) {
            std::cout << "[parity] " << c.name << " " << describe(run) << "\n";
            EXPECT_EQ(run.stats->generated(), reference.stats->clippingInvocations)
                << c.name << ": " << backend << " sends " << run.stats->generated()
                << " triangles to the clipper in " << c.pass << ", hulldomain " << reference.stats->clippingInvocations
                << "\n  " << describe(run) << "\n  " << describe(reference) << "\n  " << run.command << "\n  "
                << reference.command;
        }

        auto actual = readPng(run.screenshot);
        EXPECT_TRUE(actual.ok()) << run.screenshot;
        if (!actual.ok()) continue;
        const std::string diffPath = (testOutputDir("backend_parity") / (c.name + "." + backend + ".diff.png")).string();
        std::filesystem::remove(diffPath);
        const auto cmp = compareImages(actual.value(), expected.value(), kParityTolerance, diffPath);
        const PixelDelta delta = pixelDelta(actual.value(), expected.value());
        std::cout << "[parity] " << c.name << " " << backend << " vs hulldomain: " << delta.anyDifference
                  << " pixels differ at all (max channel difference " << delta.maxChannel << "), "
                  << cmp.differingFraction * 100.0 << "% by more than " << kParityTolerance.channelThreshold
                  << ", mean difference " << cmp.meanDifference << "\n";
        EXPECT_TRUE(cmp.match) << c.name << ": " << backend << " vs hulldomain: " << cmp.message << "\n  "
                               << run.command << "\n  " << reference.command;
    }
}

INSTANTIATE_TEST_SUITE_P(Cases, BackendParity, ::testing::ValuesIn(parityCases()),
                         [](const auto& test) { return test.param.name; });

// The comparison is not vacuous: on hulldomain alone, continuous level 3.7
// against 3.9 (the same odd segment count, only the fractional positions
// move) changes the image beyond the tolerance while leaving the triangle
// count equal, and against 5.2 (two more segments per edge) also the count.
TEST(BackendParitySensitivity, DetectsAChangedLevel) {
    auto runLevel = [](const std::string& name, const std::string& level) {
        return runBackend({name, "terrain.continuous", {"--terrain-mode", "continuous", "--tess-level", level}},
                          kReference);
    };
    const BackendRun base = runLevel("sensitivity_l3_7", "3.7");
    const BackendRun moved = runLevel("sensitivity_l3_9", "3.9");
    const BackendRun more = runLevel("sensitivity_l5_2", "5.2");
    for (const BackendRun* run : {&base, &moved, &more}) {
        ASSERT_EQ(run->result.exitCode, 0) << run->command << "\n" << run->result.output;
        ASSERT_TRUE(run->stats) << run->command << ": " << run->error;
    }
    EXPECT_EQ(moved.stats->clippingInvocations, base.stats->clippingInvocations);
    EXPECT_GT(more.stats->clippingInvocations, base.stats->clippingInvocations);

    auto a = readPng(base.screenshot);
    auto b = readPng(moved.screenshot);
    ASSERT_TRUE(a.ok() && b.ok());
    const std::string diffPath = (testOutputDir("backend_parity") / "sensitivity_l3_9.diff.png").string();
    const auto cmp = compareImages(b.value(), a.value(), kParityTolerance, diffPath);
    const PixelDelta delta = pixelDelta(b.value(), a.value());
    std::cout << "[parity] level 3.9 vs 3.7 on hulldomain: " << delta.anyDifference << " pixels differ at all, "
              << cmp.differingFraction * 100.0 << "% by more than " << kParityTolerance.channelThreshold
              << ", mean difference " << cmp.meanDifference << "\n";
    EXPECT_FALSE(cmp.match) << "a fractional level change went unnoticed: " << delta.anyDifference
                            << " pixels differ at all";
}

// `--bench terrain --backend all`: every backend in one run, at the emulated
// tessellator's maximum level, with a Chrome trace per backend. The bench's
// own views (far over the whole map, close up) must give every backend the
// triangles hulldomain draws, row by row, and the records carry the per-pass
// figures and the intermediate memory of the side-by-side table.
TEST(BackendParityBench, BackendAllAgreesOnTrianglesAndWritesATracePerBackend) {
    const auto dir = testOutputDir("backend_parity") / "bench_all";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const std::string out = (dir / "terrain.json").string();
    const std::vector<std::string> args = {"--bench", "terrain",  "--backend", "all",   "--validation",
                                           "--width", "160",      "--height",  "90",    "--frames",
                                           "1",       "--warmup", "1",         "--out", out};
    const auto run = runDemo(args);
    ASSERT_EQ(run.exitCode, 0) << commandLine(args) << "\n" << run.output;
    EXPECT_NE(run.output.find("validation messages: 0"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("Backends side by side"), std::string::npos) << run.output;

    nlohmann::json records;
    std::string error;
    ASSERT_TRUE(readJsonFile(out, records, error)) << out << ": " << error;
    ASSERT_TRUE(records.is_array()) << out;
    // Every backend the device runs: the three D3D9-to-D3D11 generations
    // always, meshshader where the device has mesh shaders.
    std::vector<std::string> backends;
    for (const nlohmann::json& r : records) {
        const std::string backend = stringAt(r, "backend").value_or("?");
        if (std::find(backends.begin(), backends.end(), backend) == backends.end()) backends.push_back(backend);
    }
    for (const char* required : {"hulldomain", "r2vb", "streamout"})
        EXPECT_NE(std::find(backends.begin(), backends.end(), required), backends.end()) << required << " missing";
    // 2 views x (lowres, continuous, adaptive with 4 metrics) per backend.
    EXPECT_EQ(records.size(), 2u * 6u * backends.size()) << out;

    size_t compared = 0;
    for (const nlohmann::json& r : records) {
        // Every value a string or a number: the records stay flat objects.
        for (const auto& member : r.items())
            EXPECT_TRUE(member.value().is_string() || member.value().is_number())
                << "\"" << member.key() << "\" is not flat in " << out;
        const std::string backend = stringAt(r, "backend").value_or("?");
        const std::string mode = stringAt(r, "mode").value_or("?");
        const std::string row =
            backend + " " + stringAt(r, "view").value_or("?") + " " + mode + " " + stringAt(r, "metric").value_or("?");
        SCOPED_TRACE(row);
        const std::string pass = "pass:terrain." + mode + ":clipping_invocations";
        ASSERT_TRUE(numberAt(r, pass)) << "no " << pass;
        EXPECT_EQ(numberAt(r, "clipping_invocations"), numberAt(r, pass));
        EXPECT_GT(numberAt(r, "clipping_invocations").value_or(0.0), 0.0);
        if (mode == "adaptive") {
            EXPECT_EQ(numberAt(r, "tess_max").value_or(0.0), 14.99);
        }
        if (mode == "continuous") {
            EXPECT_EQ(numberAt(r, "continuous_level").value_or(0.0), 14.99);
        }
        ASSERT_TRUE(numberAt(r, "clipping_invocations_vs_hulldomain")) << "no hulldomain record to compare with";
        EXPECT_EQ(*numberAt(r, "clipping_invocations_vs_hulldomain"), 1.0)
            << backend << " draws " << numberAt(r, "clipping_invocations").value_or(0.0)
            << " triangles where hulldomain draws "
            << numberAt(r, "clipping_invocations").value_or(0.0) / *numberAt(r, "clipping_invocations_vs_hulldomain")
            << "\n  " << commandLine(args);
        if (backend != kReference && mode != "lowres") {
            EXPECT_GT(numberAt(r, "intermediate_bytes").value_or(0.0), 0.0) << "no intermediate buffers reported";
        }
        const std::string trace = stringAt(r, "trace").value_or("");
        EXPECT_EQ(trace, (dir / ("bench-" + backend + ".json")).string());
        compared += backend != kReference;
    }
    EXPECT_EQ(compared, 2u * 6u * (backends.size() - 1));

    for (const std::string& backend : backends) {
        const auto path = dir / ("bench-" + backend + ".json");
        nlohmann::json trace;
        ASSERT_TRUE(readJsonFile(path, trace, error)) << path << ": " << error;
        const nlohmann::json* events = memberOf(trace, "traceEvents");
        ASSERT_TRUE(events && events->is_array()) << path;
        size_t terrainPasses = 0;
        for (const nlohmann::json& e : *events)
            terrainPasses +=
                stringAt(e, "cat") == std::string("gpu") && stringAt(e, "name").value_or("").rfind("terrain.", 0) == 0;
        // Every row's warm-up and measured frame: 12 rows x 2 frames.
        EXPECT_GE(terrainPasses, 24u) << path;
        const nlohmann::json* meta = memberOf(trace, "metadata");
        ASSERT_TRUE(meta) << path;
        EXPECT_EQ(stringAt(*meta, "backend"), backend) << path;
    }
}
