// Every exported .glb passes the Khronos glTF-Validator with zero errors.
// The validator is the npm package pinned in tools/gltf-validator/package.json,
// installed by `./tessera test` into <build>/npm when npm is available; without
// node or the package these tests are skipped, saying why.
#include "GlbTestCharacter.h"
#include "creature/GlbExporter.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>

namespace {

namespace fs = std::filesystem;

fs::path outputDir() {
    fs::path dir = fs::path(TESSERA_TEST_OUTPUT_DIR) / "gltf_validator";
    fs::create_directories(dir);
    return dir;
}

fs::path modulesDir() { return fs::path(TESSERA_BINARY_DIR) / "npm" / "node_modules"; }

// The node executable on PATH ("node", or Debian's older "nodejs"), or empty.
fs::path findNode() {
    const char* path = std::getenv("PATH");
    std::stringstream dirs(path ? path : "");
    for (std::string dir; std::getline(dirs, dir, ':');) {
        for (const char* name : {"node", "nodejs"}) {
            fs::path candidate = fs::path(dir) / name;
            std::error_code ec;
            if (!dir.empty() && fs::is_regular_file(candidate, ec)) return candidate;
        }
    }
    return {};
}

// Why the validator cannot run here, or "" when it can.
std::string missingValidator() {
    if (findNode().empty()) return "node is not on PATH";
    if (!fs::exists(modulesDir() / "gltf-validator" / "package.json")) {
        return "the gltf-validator npm package is not installed in " + modulesDir().string() +
               " (./tessera test installs it when npm and the network are available)";
    }
    return "";
}

std::string quoted(const fs::path& p) {
    std::string out = "'";
    for (char c : p.string()) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

// Runs tools/gltf-validator/validate.js on `file` and returns its report.
nlohmann::json validate(const fs::path& file) {
    fs::path script = fs::path(TESSERA_SOURCE_DIR) / "tools" / "gltf-validator" / "validate.js";
    std::string command = quoted(findNode()) + " " + quoted(script) + " " + quoted(modulesDir()) + " " + quoted(file);
    std::string output;
    if (FILE* pipe = popen(command.c_str(), "r")) {
        char buffer[4096];
        for (size_t n; (n = fread(buffer, 1, sizeof buffer, pipe)) > 0;) output.append(buffer, n);
        pclose(pipe);
    }
    nlohmann::json report = nlohmann::json::parse(output, nullptr, false);
    EXPECT_FALSE(report.is_discarded()) << file << ": the validator printed no report:\n" << output;
    return report.is_discarded() ? nlohmann::json::object() : report;
}

// Validates `file`, expects zero errors, prints every message that is not
// an error, and returns the report's messages.
nlohmann::json expectValid(const fs::path& file) {
    nlohmann::json report = validate(file);
    const auto& issues = report.value("issues", nlohmann::json::object());
    EXPECT_EQ(issues.value("numErrors", -1), 0) << file << ":\n" << issues.dump(2);
    std::printf("%s: %zu bytes, %d errors, %d warnings, %d infos\n", file.filename().c_str(),
                size_t(fs::file_size(file)), issues.value("numErrors", -1), issues.value("numWarnings", -1),
                issues.value("numInfos", -1));
    for (const auto& message : issues.value("messages", nlohmann::json::array())) {
        std::printf("  [%d] %s %s: %s\n", message.value("severity", -1), message.value("code", "").c_str(),
                    message.value("pointer", "").c_str(), message.value("message", "").c_str());
    }
    return issues.value("messages", nlohmann::json::array());
}

void exportOrFail(const tessera::character::CharacterAsset& asset, const fs::path& file, bool draco) {
    tessera::creature::ExportOptions options;
    options.draco = draco;
    auto status = tessera::creature::exportGlb(asset, file, options);
    ASSERT_TRUE(status.ok()) << status.error().message;
}

TEST(GltfValidator, SyntheticCharacterHasNoErrors) {
    if (std::string why = missingValidator(); !why.empty()) GTEST_SKIP() << "SKIPPED: " << why;
    for (bool draco : {false, true}) {
        fs::path file = outputDir() / (draco ? "synthetic_draco.glb" : "synthetic_plain.glb");
        exportOrFail(tessera::test::makeTestCharacter(), file, draco);
        nlohmann::json messages = expectValid(file);
        if (draco) {
            // The validator cannot decode Draco: it says so as an info, not an error.
            bool noted = std::any_of(messages.begin(), messages.end(), [](const auto& m) {
                return m.value("code", "") == "UNSUPPORTED_EXTENSION" && m.value("severity", 0) > 0;
            });
            EXPECT_TRUE(noted);
        }
    }
}

// Over 255 joints and 65535 vertices: uint16 joints and uint32 indices.
TEST(GltfValidator, WideCharacterHasNoErrors) {
    if (std::string why = missingValidator(); !why.empty()) GTEST_SKIP() << "SKIPPED: " << why;
    tessera::character::CharacterAsset asset = tessera::test::makeTestCharacter(320, 210);
    for (uint32_t j = 0; j < 300; ++j) {
        tessera::character::SkeletonNode node;
        node.name = "extra" + std::to_string(j);
        node.parent = 0;
        asset.skeleton.nodes.push_back(node);
        asset.cage.bindings.push_back({static_cast<uint32_t>(asset.skeleton.nodes.size() - 1), glm::mat4(1.0f)});
    }
    asset.cage.vertices[5].joints = {300, 0, 0, 0};
    asset.cage.vertices[5].weights = {1.0f, 0.0f, 0.0f, 0.0f};
    ASSERT_GT(asset.cage.vertices.size(), 65535u);
    for (bool draco : {false, true}) {
        fs::path file = outputDir() / (draco ? "wide_draco.glb" : "wide_plain.glb");
        exportOrFail(asset, file, draco);
        expectValid(file);
    }
}

// The creatures the build generates (tessera-creaturegen), when present.
TEST(GltfValidator, GeneratedCreaturesHaveNoErrors) {
    if (std::string why = missingValidator(); !why.empty()) GTEST_SKIP() << "SKIPPED: " << why;
    fs::path dir = fs::path(TESSERA_BINARY_DIR) / "content" / "characters";
    std::vector<fs::path> files;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(dir, ec)) {
        if (entry.path().extension() == ".glb") files.push_back(entry.path());
    }
    if (files.empty()) GTEST_SKIP() << "SKIPPED: no generated creatures in " << dir << " (built by tessera-creaturegen)";
    std::sort(files.begin(), files.end());
    for (const fs::path& file : files) expectValid(file);
}

} // namespace
