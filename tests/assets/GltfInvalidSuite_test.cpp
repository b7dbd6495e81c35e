// The glTF-Validator's test suite: every file its report marks with errors
// must be rejected with a one-line message naming the file; no file may
// crash. Also Draco's, tinygltf's and the Asset Generator's files: each loads
// or fails cleanly. (Also built under ASan+UBSan as tessera_asset_asan_tests.)
#include "tessera/assets/GltfLoader.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;
using tessera::assets::loadCharacter;

namespace {

const fs::path kTestData = TESSERA_TESTDATA_DIR;

std::vector<fs::path> filesUnder(const fs::path& folder, std::initializer_list<const char*> extensions) {
    std::vector<fs::path> files;
    for (const auto& entry : fs::recursive_directory_iterator(folder)) {
        if (!entry.is_regular_file()) continue;
        std::string name = entry.path().filename().string();
        for (const char* ext : extensions)
            if (name.size() > std::strlen(ext) && name.compare(name.size() - std::strlen(ext), std::strlen(ext), ext) == 0)
                files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

} // namespace

TEST(GltfInvalidSuite, RejectsEveryFileTheValidatorReportsErrorsFor) {
    const fs::path suite = kTestData / "bad/gltf-validator";
    ASSERT_TRUE(fs::is_directory(suite)) << suite;
    size_t invalid = 0, rejected = 0, valid = 0;
    std::vector<std::string> failures;
    for (const fs::path& report : filesUnder(suite, {".report.json"})) {
        fs::path input = report;
        input.replace_extension("");
        input.replace_extension("");  // x.gltf.report.json -> x.gltf
        std::string name = report.filename().string();
        input = report.parent_path() / name.substr(0, name.size() - std::string(".report.json").size());
        if (!fs::exists(input)) continue;
        std::ifstream in(report);
        nlohmann::json expected = nlohmann::json::parse(in);
        auto result = loadCharacter(input);
        if (!result) {
            const std::string& message = result.error().message;
            EXPECT_EQ(message.find('\n'), std::string::npos) << message;
            EXPECT_EQ(message.rfind(input.string(), 0), 0u) << message;
        }
        if (expected["issues"]["numErrors"].get<int>() == 0) {
            ++valid;
            continue;
        }
        ++invalid;
        if (!result) {
            ++rejected;
            continue;
        }
        std::string codes;
        for (const auto& m : expected["issues"]["messages"])
            if (m["severity"] == 0) {
                // Appended piecewise: GCC 12's -Wrestrict misfires on "..." + std::string&&.
                codes += ' ';
                codes += m["code"].get<std::string>();
                codes += '@';
                codes += m.value("pointer", "");
            }
        failures.push_back(fs::relative(input, suite).string() + ":" + codes);
    }
    std::string list;
    for (const std::string& f : failures) list += "\n  " + f;
    EXPECT_TRUE(failures.empty()) << failures.size() << " invalid files loaded:" << list;
    std::printf("glTF-Validator suite: %zu invalid files, %zu rejected; %zu without errors\n", invalid, rejected, valid);
    EXPECT_GT(invalid, 200u);
}

TEST(GltfInvalidSuite, OtherBadFilesLoadOrFailCleanly) {
    size_t files = 0, loaded = 0;
    for (const char* folder : {"bad/draco", "bad/tinygltf", "bad/asset-generator"}) {
        for (const fs::path& input : filesUnder(kTestData / folder, {".gltf", ".glb"})) {
            ++files;
            auto result = loadCharacter(input);
            if (result) {
                ++loaded;
                EXPECT_FALSE(result->cage.indices.empty()) << input;
            } else {
                EXPECT_EQ(result.error().message.rfind(input.string(), 0), 0u) << result.error().message;
            }
        }
    }
    std::printf("draco/tinygltf/asset-generator: %zu files, %zu loaded\n", files, loaded);
    EXPECT_GT(files, 10u);
}
