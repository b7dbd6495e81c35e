#pragma once
/// @file SceneOptions.h
/// Options for the runtime tests' small in-process scenes.

#include "tessera/runtime/Options.h"

#include <string>

namespace tessera::test {

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
