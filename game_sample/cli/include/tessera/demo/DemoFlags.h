#pragma once
/// @file DemoFlags.h
/// tessera-demo's flags, declared once on the shared command-line parser
/// (tessera::cli::CommandLine): each with its group, argument name, check
/// and the description --help prints. Plain values land in Options
/// directly; the rest in DemoFlagText for CommandLine.cpp to interpret.

#include "tessera/cli/CommandLine.h"
#include "tessera/runtime/Options.h"

#include <cstdint>
#include <string>
#include <vector>

namespace tessera::demo {

/// Flags read as text first: lists, pairs, words that map to enums, and
/// optional numbers (given or not is part of their meaning).
struct DemoFlagText {
    std::vector<std::string> models, splats;
    std::string agents, clearColor, camera, subdivLevel, orbitDistance;
    std::string characterPath, normals, subdivView, sculpt, terrainMode, tessMetric, look, terrainShading, shadows, sun;
    std::string hideFeatures;
    float lodNear = 0, lodFar = 0, lodImpostor = 0, lodEdge = 0, characterLevel = 0, subdivPixels = 0;
    uint64_t lodBudget = 0, subdivBudget = 0, deviceMemoryCap = 0;
    uint32_t lodMiddleMax = 0, lodFarMax = 0, lodFade = 0, lodFarTriangles = 0, lodMiddleTriangles = 0, lodNearMax = 0, renderdocFrame = 0;
    uint32_t lodFarCasterTriangles = 0;
};

/// Declares every flag of tessera-demo on `line`, bound to `options` and `text`.
void declareDemoFlags(cli::CommandLine& line, runtime::Options& options, DemoFlagText& text);

} // namespace tessera::demo
