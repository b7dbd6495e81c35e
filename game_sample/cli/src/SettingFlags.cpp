#include "tessera/demo/SettingFlags.h"

#include <algorithm>
#include <array>

namespace tessera::demo {
namespace {

// Sorted by the libraries' words (tests/runtime/setting_flags_test.cpp
// checks the order and that every word of the runtime's vocabulary,
// tessera/runtime/Settings.h, has its flag here). An action the runtime
// advises ("list the backends") maps to the demo's way of doing it.
constexpr std::array kSettingFlags = std::to_array<SettingFlag>({
    {"RenderDoc frame", "--renderdoc"},
    {"agents", "--agents"},
    {"agents drawn", "--crowd-draw"},
    {"backend", "--backend"},
    {"benchmark output", "--out"},
    {"camera pose", "--camera"},
    {"character level", "--character-level"},
    {"character surface", "--character-surface"},
    {"characters benchmark", "--bench characters"},
    {"continuous tessellation level", "--tess-level"},
    {"creatures", "--crowd"},
    {"crowd benchmark", "--bench crowd"},
    {"crowd simulation benchmark", "--bench crowd-sim"},
    {"crowd tiers", "--crowd-tiers"},
    {"device", "--device"},
    {"device memory cap", "--device-memory-cap"},
    {"frame recording", "--record"},
    {"frame size", "--width/--height"},
    {"height dump", "--dump-heights"},
    {"height map", "--heightmap"},
    {"list the backends", "run --list-backends"},
    {"maximum tessellation level", "--tess-max"},
    {"models", "--model"},
    {"overlay", "--overlay"},
    {"scene", "--scene"},
    {"screenshot", "--screenshot"},
    {"shadows", "--shadows"},
    {"subdivision benchmark", "--bench subdiv"},
    {"subdivision level", "--subdiv-level"},
    {"terrain benchmark", "--bench terrain"},
    {"terrain mode", "--terrain-mode"},
    {"trace directory", "--out-dir"},
    {"validation", "--validation"},
    {"window", "--window"},
    {"wireframe", "--wireframe"},
});

} // namespace

std::span<const SettingFlag> settingFlags() { return kSettingFlags; }

std::string flagFor(std::string_view words) {
    const auto it = std::find_if(kSettingFlags.begin(), kSettingFlags.end(),
                                 [words](const SettingFlag& entry) { return entry.words == words; });
    return std::string(it != kSettingFlags.end() ? it->flag : words);
}

std::string withFlags(const Error& error) { return error.naming(flagFor(error.setting)); }

} // namespace tessera::demo
