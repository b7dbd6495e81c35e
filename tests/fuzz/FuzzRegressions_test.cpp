// Replays what the fuzzers found (tools/fuzz, docs/RELIABILITY.md): each
// file under tests/fuzz/regressions/<harness>/ once crashed, leaked or hung
// its harness. Fed through the same entry point, it must now give a value
// or an error with a message, in the ordinary release build.
#include "tessera/demo/CommandLine.h"
#include "tessera/assets/GltfLoader.h"
#include "tessera/subdiv/ObjShape.h"
#include "tessera/terrain/HeightMapIO.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

std::vector<fs::path> regressions(const std::string& harness) {
    std::vector<fs::path> files;
    const fs::path dir = fs::path(TESSERA_FUZZ_REGRESSIONS_DIR) / harness;
    if (fs::is_directory(dir))
        for (const auto& entry : fs::directory_iterator(dir))
            if (entry.is_regular_file() && entry.path().filename() != "README.md") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    std::cout << "[fuzz regressions] " << harness << ": " << files.size() << " files\n";
    return files;
}

std::string readText(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// The harness writes its input under a name with the loader's extension.
fs::path asFile(const fs::path& input, const std::string& extension) {
    const fs::path out = fs::path(TESSERA_TEST_OUTPUT_DIR) / "fuzz_regressions" / (input.filename().string() + extension);
    fs::create_directories(out.parent_path());
    fs::copy_file(input, out, fs::copy_options::overwrite_existing);
    return out;
}

} // namespace

TEST(FuzzRegressions, GltfFilesLoadOrFailWithAMessage) {
    for (const auto& input : regressions("gltf")) {
        const std::string bytes = readText(input);
        const bool glb = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
        auto loaded = tessera::assets::loadCharacter(asFile(input, glb ? ".glb" : ".gltf"));
        if (!loaded.ok()) {
            EXPECT_FALSE(loaded.error().message.empty()) << input;
        }
    }
}

TEST(FuzzRegressions, HeightMapsLoadOrFailWithAMessage) {
    for (const auto& input : regressions("heightmap")) {
        auto field = tessera::terrain::loadHeightMapPng(asFile(input, ".png"));
        if (!field.ok()) {
            EXPECT_FALSE(field.error().message.empty()) << input;
        }
    }
}

TEST(FuzzRegressions, ObjShapesParseOrFailWithAMessage) {
    for (const auto& input : regressions("obj")) {
        auto shape = tessera::subdiv::parseObjShape(readText(input), input.filename().string());
        if (!shape.ok()) {
            EXPECT_FALSE(shape.error().message.empty()) << input;
        }
    }
}

TEST(FuzzRegressions, CommandLinesParseOrFailWithAMessage) {
    for (const auto& input : regressions("cli")) {
        std::vector<std::string> args(1);
        for (char c : readText(input)) {
            if (c == '\n' || c == '\0')
                args.emplace_back();
            else
                args.back() += c;
        }
        if (args.back().empty()) args.pop_back();
        auto options = tessera::demo::parseCommandLine(args);
        if (!options.ok()) {
            EXPECT_FALSE(options.error().message.empty()) << input;
        }
    }
}
