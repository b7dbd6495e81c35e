#include "tessera/runtime/Settings.h"

#include <array>

namespace tessera::runtime::setting {

std::span<const char* const> all() {
    static constexpr std::array<const char*, 34> kAll = {
        kBackend,        kDevice,          kListBackends,     kDeviceMemoryCap,   kWireframe,
        kWindow,         kOverlay,         kFrameSize,        kRenderDocFrame,    kScreenshot,
        kRecord,         kHeightDump,      kCrowdTiers,       kHeightMap,         kScene,
        kCamera,         kModels,          kCreatures,        kAgents,            kAgentsDrawn,
        kTerrainMode,    kTessLevel,       kTessMax,          kCharacterLevel,    kCharacterSurface,
        kSubdivLevel,    kTerrainBenchmark, kCharacterBenchmark, kSubdivBenchmark, kCrowdBenchmark, kCrowdSimBenchmark,
        kBenchOutput,    kTraceDirectory,  kShadows};
    return kAll;
}

} // namespace tessera::runtime::setting
