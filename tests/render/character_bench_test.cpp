// --bench characters: the paper's character figures as JSON (two-pass against
// single-pass GPU time per backend, amplification, Table 1 bytes and the
// compressed vertex's error). Checks the document's structure and the
// invariants that hold on any device; GPU times are only checked to be there.
#include "DemoProcess.h"
#include "TestFiles.h"
#include "JsonFile.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using namespace tessera::test;

namespace {

double number(const nlohmann::json& object, const std::string& key) {
    const auto v = numberAt(object, key);
    EXPECT_TRUE(v.has_value()) << "missing number \"" << key << "\"";
    return v.value_or(-1.0);
}

const nlohmann::json& member(const nlohmann::json& object, const std::string& key) {
    static const nlohmann::json none;
    const nlohmann::json* v = memberOf(object, key);
    EXPECT_NE(v, nullptr) << "missing \"" << key << "\"";
    return v ? *v : none;
}

// The small run every check below reads: one generated creature and
// CesiumMan at level 3, two measured frames per row.
class CharacterBench : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        const std::filesystem::path dir = testOutputDir("character_bench");
        std::filesystem::remove(dir / "bench.json");
        run = new ProcessResult(runDemo({"--bench",
                                         "characters",
                                         "--backend",
                                         "all",
                                         "--crowd",
                                         "1",
                                         "--no-terrain",
                                         "--width",
                                         "160",
                                         "--height",
                                         "96",
                                         "--warmup",
                                         "1",
                                         "--frames",
                                         "2",
                                         "--character-level",
                                         "3",
                                         "--validation",
                                         "--out",
                                         (dir / "bench.json").string(),
                                         "--out-dir",
                                         dir.string()}));
        document = new nlohmann::json();
        std::string error;
        parsed = readJsonFile(dir / "bench.json", *document, error);
        parseError = error;
    }
    static void TearDownTestSuite() {
        delete run;
        delete document;
    }
    void SetUp() override {
        ASSERT_EQ(run->exitCode, 0) << run->output;
        ASSERT_TRUE(parsed) << parseError;
        ASSERT_TRUE(document->is_object());
    }

    static inline ProcessResult* run = nullptr;
    static inline nlohmann::json* document = nullptr;
    static inline bool parsed = false;
    static inline std::string parseError;
};

TEST_F(CharacterBench, RunsCleanUnderValidation) {
    EXPECT_NE(run->output.find("validation messages: 0"), std::string::npos) << run->output;
    EXPECT_EQ(stringAt(*document, "format").value_or(""), "tessera-bench-characters");
    EXPECT_EQ(number(*document, "shared_level"), 3.0);
    for (const char* backend : {"hulldomain", "r2vb", "streamout"})
        EXPECT_TRUE(std::filesystem::exists(testOutputDir("character_bench") / ("bench-characters-" + std::string(backend) + ".json")))
            << backend;
}

TEST_F(CharacterBench, EveryBackendDrawsBothPathsWithTheSameTriangles) {
    const nlohmann::json& timing = member(*document, "timing");
    ASSERT_TRUE(timing.is_array());
    std::set<std::string> seen;
    const double characters = number(*document, "characters_per_frame");
    EXPECT_EQ(characters, 2.0); // froblin_1 and CesiumMan
    const double triangles = number(timing.front(), "triangles");
    const double cage = number(timing.front(), "cage_triangles");
    EXPECT_GT(triangles, cage); // amplification > 1
    for (const nlohmann::json& row : timing) {
        const std::string name = stringAt(row, "backend").value_or("?") + " " + stringAt(row, "path").value_or("?");
        seen.insert(name);
        EXPECT_EQ(number(row, "level"), 3.0) << name;
        EXPECT_EQ(number(row, "frames"), 2.0) << name;
        EXPECT_EQ(number(row, "characters_drawn"), characters) << name;
        EXPECT_EQ(number(row, "triangles"), triangles) << name;
        EXPECT_EQ(number(row, "cage_triangles"), cage) << name;
        EXPECT_GT(number(row, "amplification"), 1.0) << name;
        // The GPU's own count (pipeline statistics, 0 where the device has
        // none) agrees with the backend's FrameReport.
        const double clipped = number(row, "clipping_invocations");
        if (clipped > 0.0) {
            EXPECT_EQ(clipped, triangles) << name;
        }
        // Present, not bounded: timings are never asserted.
        EXPECT_GE(number(row, "character_gpu_ms_median"), 0.0) << name;
        const std::string passes = stringAt(row, "passes").value_or("");
        if (stringAt(row, "path") == "two-pass") {
            EXPECT_NE(passes.find("character.skin"), std::string::npos) << name << ": " << passes;
            EXPECT_NE(passes.find("character.tessellate"), std::string::npos) << name << ": " << passes;
            EXPECT_TRUE(numberAt(row, "single_over_two_pass").has_value()) << name;
        } else {
            EXPECT_NE(passes.find("character.singlePass"), std::string::npos) << name << ": " << passes;
        }
    }
    for (const char* backend : {"hulldomain", "r2vb", "streamout"})
        for (const char* path : {"two-pass", "single-pass"})
            EXPECT_EQ(seen.count(std::string(backend) + " " + path), 1u) << backend << " " << path;
}

TEST_F(CharacterBench, AmplificationMatchesTheFrameAndThePaper) {
    const nlohmann::json& amplification = member(*document, "amplification");
    const nlohmann::json& assets = member(amplification, "characters");
    ASSERT_EQ(assets.size(), 2u);
    double perFrame = 0.0;
    for (const nlohmann::json& a : assets) {
        EXPECT_EQ(number(a, "triangles_at_shared_level"),
                  number(a, "cage_triangles") * number(a, "triangles_per_cage_triangle"));
        EXPECT_GT(number(a, "triangles_at_paper_level"), number(a, "triangles_at_shared_level"));
        perFrame += number(a, "triangles_at_shared_level");
    }
    EXPECT_EQ(perFrame, number(member(*document, "timing").front(), "triangles"));
    // The paper's 5.2K -> 1.6M is about 308x; the closest level gets within a step.
    const double ratio =
        number(amplification, "paper_level_amplification") / number(amplification, "paper_amplification");
    EXPECT_GT(ratio, 0.8);
    EXPECT_LT(ratio, 1.25);
}

TEST_F(CharacterBench, Table1CountsTheEngineFormats) {
    const nlohmann::json& table = member(*document, "table1");
    EXPECT_EQ(number(table, "level"), 3.0);
    bool displaced = false;
    for (const nlohmann::json& a : member(table, "characters")) {
        const std::string name = stringAt(a, "asset").value_or("?");
        EXPECT_EQ(number(a, "cage_bytes"), number(a, "cage_vertices") * 80 + number(a, "cage_triangles") * 12) << name;
        EXPECT_EQ(number(a, "compressed_cage_bytes"), number(a, "cage_vertices") * 16) << name;
        EXPECT_EQ(number(a, "displacement_map_bytes"),
                  number(a, "displacement_map_width") * number(a, "displacement_map_height") * 2)
            << name;
        EXPECT_EQ(number(a, "dense_bytes"), number(a, "dense_vertices") * 80 + number(a, "dense_triangles") * 12)
            << name;
        if (name.rfind("froblin_", 0) == 0) {
            displaced = number(a, "displacement_map_bytes") > 0;
            // The generator's report sits beside the generated asset.
            EXPECT_GT(number(a, "sculpt_triangles"), 1e6) << name;
        }
    }
    EXPECT_TRUE(displaced);
}

TEST_F(CharacterBench, CompressionErrorWithinTheIssuesBounds) {
    const nlohmann::json& errors = member(*document, "compression_error");
    ASSERT_EQ(errors.size(), 2u);
    for (const nlohmann::json& a : errors) {
        const std::string name = stringAt(a, "asset").value_or("?");
        EXPECT_GT(number(a, "vertices_measured"), 0.0) << name;
        EXPECT_LT(number(a, "max_position_error_relative"), 1e-4) << name;
        EXPECT_LT(number(a, "max_normal_angle_deg"), 1.0) << name;
        EXPECT_LT(number(a, "max_tangent_angle_deg"), 2.0) << name;
    }
}

TEST(CharacterBenchUsage, NoCharactersIsAOneLineError) {
    const ProcessResult r = runDemo({"--bench", "characters", "--crowd", "0", "--backend", "null"});
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("--bench characters: no characters to draw"), std::string::npos) << r.output;
}

} // namespace
