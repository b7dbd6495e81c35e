#pragma once
/// @file CrowdDemo.h
/// Shared by the crowd scene and crowd benchmark tests: a small terrain that
/// keeps their runs short, and the crowd lines the demo prints.

#include "CharacterDemo.h"
#include "SmallTerrain.h"
#include "TestFiles.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <sstream>
#include <string>

namespace tessera::test {

/// The 2 km crop of the build's content terrain (SmallTerrain.h) in the
/// test output directory, so Crowd::create solves its fields in a fraction of
/// a second.
inline std::string smallCrowdTerrain() {
    std::string error;
    const std::string path = smallTerrainCrop(buildContentDir(), testOutputDir("crowd"), error);
    EXPECT_FALSE(path.empty()) << error;
    return path;
}

/// The number before `label` in the demo's closing crowd line ("crowd: 60
/// steps (2.0 s): 1990 of 2000 agents walking, 12 fleeing, ..."), if any.
inline std::optional<long> crowdFigure(const std::string& output, const std::string& label) {
    std::istringstream lines(output);
    for (std::string line; std::getline(lines, line);) {
        if (line.rfind("crowd: ", 0) != 0 || line.find(" steps (") == std::string::npos) continue;
        std::istringstream words(line);
        std::string previous, word;
        while (words >> word) {
            if (word.rfind(label, 0) == 0 && !previous.empty()) return std::strtol(previous.c_str(), nullptr, 10);
            previous = word;
        }
    }
    return std::nullopt;
}

} // namespace tessera::test
