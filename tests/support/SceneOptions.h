#pragma once
/// @file SceneOptions.h
/// Options for the runtime tests' small in-process scenes.

#include "SmallTerrain.h"

#include "tessera/runtime/Options.h"

#include <gtest/gtest.h>

#include <string>

namespace tessera::test {

/// The 2 km crop of the content terrain (SmallTerrain.h), written once into
/// TESSERA_TEST_OUTPUT_DIR/runtime: for tests that load or re-create a scene
/// many times, where the 8 km terrain's upload and the crowd's fields over it
/// would be most of their time.
inline std::string smallTerrain() {
    std::string error;
    const std::string path =
        smallTerrainCrop(TESSERA_CONTENT_DIR, std::string(TESSERA_TEST_OUTPUT_DIR) + "/runtime", error);
    EXPECT_FALSE(path.empty()) << error;
    return path;
}

/// `scene` on `backend` at 96x64 with the build tree's plugins and content,
/// under the validation layer unless on the null backend. The crowd scene
/// gets 64 agents and one meteor: small, so a test is about what it checks
/// and not about the rasterizer.
inline runtime::Options smallSceneOptions(const std::string& backend, const std::string& scene) {
    runtime::Options options;
    options.backend = backend;
    options.pluginDirs = {TESSERA_PLUGIN_DIR};
    options.contentDir = TESSERA_CONTENT_DIR;
    options.validation = backend != "null";
    options.scene = scene;
    options.width = 96;
    options.height = 64;
    if (scene == "crowd") {
        options.agents = {64};
        options.meteors = 1;
    }
    return options;
}

} // namespace tessera::test
