// A device that lacks a feature (docs/RELIABILITY.md, "Faults"), simulated
// with --hide-features: the hidden features are neither shown to the
// backends nor enabled on the device, so the validation layer flags a
// backend that uses one anyway. A backend asked for by name refuses in one
// line naming what it needs; without --backend the selection falls back to
// the next backend that can run; a feature that only degrades the run
// (wireframe, timestamps) says so in a warning.
#include "CharacterDemo.h"
#include "CrowdDemo.h"

#include <gtest/gtest.h>

#include <sstream>

#include <string>
#include <vector>

using namespace tessera::test;

namespace {

const std::vector<std::string> kCrowd = {"--agents", "64", "--frames", "2", "--width", "96", "--height", "64",
                                         "--validation"};

ProcessResult runHiding(const std::string& features, std::vector<std::string> extra = {}) {
    std::vector<std::string> args = kCrowd;
    // The 2 km crop: the same scene, without solving the crowd's fields
    // over 8 km in every run.
    args.insert(args.end(), {"--heightmap", smallCrowdTerrain()});
    args.insert(args.end(), {"--hide-features", features});
    args.insert(args.end(), extra.begin(), extra.end());
    return runDemo(args);
}

} // namespace

// Each backend on a device with only the features it declares it needs:
// it must run the crowd scene (terrain, characters, the GPU crowd) without
// a validation message, i.e. use nothing it did not ask for.
TEST(DeviceFeatures, EveryBackendRunsOnOnlyWhatItDeclares) {
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"hulldomain", "geometry,transform-feedback,pipeline-statistics,timestamps,wireframe,vertex-stores,"
                       "multi-draw-indirect"},
        {"r2vb", "tessellation,geometry,transform-feedback,pipeline-statistics,timestamps,wireframe,vertex-stores"},
        {"streamout", "tessellation,pipeline-statistics,timestamps,wireframe,vertex-stores"},
        {"meshshader", "tessellation,geometry,transform-feedback,pipeline-statistics,timestamps,wireframe,"
                       "vertex-stores,multi-draw-indirect"},
    };
    for (const auto& [backend, hidden] : cases) {
        if (!deviceRunsBackend(backend)) continue;
        const ProcessResult run = runHiding(hidden, {"--backend", backend});
        EXPECT_EQ(run.exitCode, 0) << backend << ": " << run.output;
        EXPECT_TRUE(validationClean(run)) << backend << ": " << run.output;
        EXPECT_NE(run.output.find("backend " + backend + " on "), std::string::npos) << run.output;
    }
}

TEST(DeviceFeatures, WithoutABackendNamedTheSelectionFallsBack) {
    // The order depends on the device (BackendSelection.h): streamout first
    // on a CPU rasterizer, hulldomain first on a GPU. Hiding what the first
    // needs falls back to the second, saying why.
    bool cpu = false;
    std::istringstream devices(runDemo({"--list-devices"}).output);
    for (std::string line; std::getline(devices, line);)
        if (line.find("[default]") != std::string::npos) cpu = line.find("(CPU)") != std::string::npos;
    const std::string firstNeeds = cpu ? "transform-feedback" : "tessellation";
    const std::string why = cpu ? "it needs transform feedback (VK_EXT_transform_feedback); trying the next backend"
                                : "it needs tessellation shaders (tessellationShader); trying the next backend";
    const std::string second = cpu ? "hulldomain" : "streamout";
    const ProcessResult fallback = runHiding(firstNeeds);
    EXPECT_EQ(fallback.exitCode, 0) << fallback.output;
    EXPECT_NE(fallback.output.find(why), std::string::npos) << fallback.output;
    EXPECT_NE(fallback.output.find("backend " + second + " on "), std::string::npos) << fallback.output;
    EXPECT_TRUE(validationClean(fallback)) << fallback.output;

    const ProcessResult d3d9Class = runHiding("tessellation,transform-feedback");
    EXPECT_EQ(d3d9Class.exitCode, 0) << d3d9Class.output;
    EXPECT_NE(d3d9Class.output.find("backend r2vb on "), std::string::npos) << d3d9Class.output;
    EXPECT_TRUE(validationClean(d3d9Class)) << d3d9Class.output;

    // Without what the three older generations need, the fourth still runs
    // where the device has mesh shaders; without those too, none does.
    if (deviceRunsBackend("meshshader")) {
        const ProcessResult meshOnly = runHiding("tessellation,transform-feedback,multi-draw-indirect");
        EXPECT_EQ(meshOnly.exitCode, 0) << meshOnly.output;
        EXPECT_NE(meshOnly.output.find("backend meshshader on "), std::string::npos) << meshOnly.output;
        EXPECT_TRUE(validationClean(meshOnly)) << meshOnly.output;
    }
    expectOneLineError({"--hide-features", "tessellation,transform-feedback,multi-draw-indirect,mesh-shader", "--scene",
                        "terrain", "--validation"},
                       1, "no backend can run on this device; run --list-backends for details");
}

TEST(DeviceFeatures, ABackendNamedRefusesNamingWhatItNeeds) {
    expectOneLineError({"--backend", "streamout", "--hide-features", "geometry", "--scene", "terrain", "--validation"},
                       1, "backend streamout cannot run on");
    expectOneLineError({"--backend", "hulldomain", "--hide-features", "tessellation", "--scene", "terrain",
                        "--validation"},
                       1, "it needs tessellation shaders (tessellationShader)");
    expectOneLineError({"--backend", "meshshader", "--hide-features", "mesh-shader", "--scene", "terrain",
                        "--validation"},
                       1, "it needs task and mesh shaders (VK_EXT_mesh_shader)");
    const ProcessResult listed = runDemo({"--list-backends", "--hide-features", "multi-draw-indirect"});
    EXPECT_EQ(listed.exitCode, 0) << listed.output;
    EXPECT_NE(listed.output.find("missing: indirect draws with many commands and a first instance"), std::string::npos)
        << listed.output;
}

TEST(DeviceFeatures, WhatOnlyDegradesTheRunIsAWarning) {
    const ProcessResult run = runDemo({"--scene", "terrain", "--frames", "2", "--width", "64", "--height", "64",
                                       "--validation", "--hide-features", "wireframe,timestamps", "--wireframe",
                                       "--benchmark", (testOutputDir("features") / "bench.json").string()});
    EXPECT_EQ(run.exitCode, 0) << run.output;
    EXPECT_TRUE(validationClean(run)) << run.output;
    EXPECT_NE(run.output.find("has no wireframe fill mode (fillModeNonSolid); drawing solid"), std::string::npos)
        << run.output;
    EXPECT_NE(run.output.find("has no timestamp queries on its graphics queue"), std::string::npos) << run.output;
}

TEST(DeviceFeatures, AnUnknownFeatureIsAUsageError) {
    expectOneLineError({"--hide-features", "tessellation,warp-drive"}, 2,
                       "--hide-features: unknown feature \"warp-drive\" (known: tessellation, geometry,");
}
