#pragma once
/// @file CrowdDemo.h
/// Shared by the crowd scene and crowd benchmark tests: a small terrain that
/// keeps their runs short, and the crowd lines the demo prints.

#include "CharacterDemo.h"
#include "TestFiles.h"

#include "tessera/terrain/HeightMapIO.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <sstream>
#include <string>

namespace tessera::test {

/// A 513 x 513 crop (2 km) of the middle of the build's content terrain, at
/// its spacing: the same kind of ground, with a sixteenth of the cells, so
/// Crowd::create solves its fields in a fraction of a second. Written once
/// into the test output directory.
inline std::string smallCrowdTerrain() {
    constexpr uint32_t kSize = 513;
    const std::filesystem::path out = testOutputDir("crowd") / "height_513.png";
    if (std::filesystem::exists(out)) return out.string();
    auto field = terrain::loadHeightMapPng(buildContentDir() / "terrain" / "height.png");
    EXPECT_TRUE(field.ok()) << (field.ok() ? "" : field.error().message);
    if (!field.ok()) return {};
    const terrain::HeightField& h = field.value();
    const uint32_t x0 = (h.width() - kSize) / 2, z0 = (h.height() - kSize) / 2;
    std::vector<uint16_t> samples;
    samples.reserve(size_t(kSize) * kSize);
    for (uint32_t j = 0; j < kSize; ++j)
        for (uint32_t i = 0; i < kSize; ++i) samples.push_back(h.samples()[size_t(z0 + j) * h.width() + x0 + i]);
    const std::filesystem::path partial = out.string() + ".partial";
    auto written = terrain::saveHeightMapPng16(partial, kSize, kSize, samples);
    EXPECT_TRUE(written.ok()) << (written.ok() ? "" : written.error().message);
    std::filesystem::rename(partial, out);
    return out.string();
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
