#pragma once
/// @file Settings.h
/// The runtime's words for the caller's settings (the fields of Options) and
/// for what it advises a caller to do, as its messages name them.
///
/// The runtime speaks its own language: an error or warning about one of
/// the caller's settings begins with the setting's words here and records
/// them (failSetting, Error::setting: "terrain mode lowres: backend r2vb does
/// not draw it ..."), and advice inside a message names settings through
/// Reporter::name() ("ask for less (agents, frame size, ...)"). A host that
/// takes the settings under other names, as tessera-demo takes flags, maps
/// these words to its own (game_sample/SettingFlags.cpp); all() lists them so
/// such a table can be checked for gaps.

#include <span>

namespace tessera::runtime::setting {

inline constexpr const char* kBackend = "backend";                       ///< Options::backend
inline constexpr const char* kDevice = "device";                         ///< Options::device
inline constexpr const char* kListBackends = "list the backends";        ///< advice: Options::listBackends
inline constexpr const char* kDeviceMemoryCap = "device memory cap";     ///< Options::deviceMemoryCap
inline constexpr const char* kWireframe = "wireframe";                   ///< Options::wireframe
inline constexpr const char* kWindow = "window";                         ///< Options::window
inline constexpr const char* kOverlay = "overlay";                       ///< Options::overlay
inline constexpr const char* kFrameSize = "frame size";                  ///< Options::width, height
inline constexpr const char* kRenderDocFrame = "RenderDoc frame";        ///< Options::renderdocFrame
inline constexpr const char* kScreenshot = "screenshot";                 ///< Options::screenshot
inline constexpr const char* kRecord = "frame recording";                ///< Options::record
inline constexpr const char* kHeightDump = "height dump";                ///< Options::dumpHeights
inline constexpr const char* kCrowdTiers = "crowd tiers";                ///< Options::crowdTiers
inline constexpr const char* kHeightMap = "height map";                  ///< Options::heightmap
inline constexpr const char* kScene = "scene";                           ///< Options::scene
inline constexpr const char* kCamera = "camera pose";                    ///< Options::camera
inline constexpr const char* kModels = "models";                         ///< Options::models, surfaces
inline constexpr const char* kCreatures = "creatures";                   ///< Options::crowd
inline constexpr const char* kAgents = "agents";                         ///< Options::agents
inline constexpr const char* kAgentsDrawn = "agents drawn";              ///< Options::crowdDraw
inline constexpr const char* kTerrainMode = "terrain mode";              ///< Options::terrainMode
inline constexpr const char* kShadows = "shadows";                       ///< Options::shadows
inline constexpr const char* kTessLevel = "continuous tessellation level"; ///< TessellationOptions::continuousLevel
inline constexpr const char* kTessMax = "maximum tessellation level";    ///< TessellationOptions::maxLevel
inline constexpr const char* kCharacterLevel = "character level";        ///< Options::characterLevel
inline constexpr const char* kCharacterSurface = "character surface";    ///< Options::characterSurface
inline constexpr const char* kSubdivLevel = "subdivision level";         ///< SubdivOptions::level
inline constexpr const char* kTerrainBenchmark = "terrain benchmark";    ///< Options::bench "terrain"
inline constexpr const char* kCharacterBenchmark = "characters benchmark"; ///< Options::bench "characters"
inline constexpr const char* kSubdivBenchmark = "subdivision benchmark"; ///< Options::bench "subdiv"
inline constexpr const char* kCrowdBenchmark = "crowd benchmark";        ///< Options::bench "crowd"
inline constexpr const char* kCrowdSimBenchmark = "crowd simulation benchmark"; ///< Options::bench "crowd-sim"
inline constexpr const char* kBenchOutput = "benchmark output";          ///< Options::benchOut
inline constexpr const char* kTraceDirectory = "trace directory";        ///< Options::benchOutDir

/// Every word above.
std::span<const char* const> all();

} // namespace tessera::runtime::setting
