#pragma once
/// @file TestFiles.h
/// Files the tests write and read back: their output folders and whole-file
/// reads.

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace tessera::test {

/// TESSERA_TEST_OUTPUT_DIR/`name`, created if missing (screenshots, JSON and
/// diff images stay there for inspection after a failure).
inline std::filesystem::path testOutputDir(const std::string& name) {
    const std::filesystem::path dir = std::filesystem::path(TESSERA_TEST_OUTPUT_DIR) / name;
    std::filesystem::create_directories(dir);
    return dir;
}

/// The whole file as text; empty when it cannot be read.
inline std::string readTextFile(const std::filesystem::path& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

} // namespace tessera::test
