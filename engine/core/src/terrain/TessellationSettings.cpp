#include "tessera/terrain/TessellationSettings.h"

#include "tessera/shaders/TessFactors.h"

namespace tessera::terrain {

// The shaders receive these enums as raw integers (TerrainTessUniforms::mode),
// so the values are pinned to the shared header's ids.
static_assert(uint32_t(TerrainMode::LowRes) == TS_TERRAIN_MODE_LOWRES);
static_assert(uint32_t(TerrainMode::Continuous) == TS_TERRAIN_MODE_CONTINUOUS);
static_assert(uint32_t(TerrainMode::Adaptive) == TS_TERRAIN_MODE_ADAPTIVE);
static_assert(uint32_t(TessMetric::ScreenEdge) == TS_METRIC_SCREEN);
static_assert(uint32_t(TessMetric::Distance) == TS_METRIC_DISTANCE);
static_assert(uint32_t(TessMetric::Silhouette) == TS_METRIC_SILHOUETTE);
static_assert(uint32_t(TessMetric::HeightDetail) == TS_METRIC_DETAIL);

const char* toString(TerrainMode mode) {
    switch (mode) {
    case TerrainMode::LowRes: return "lowres";
    case TerrainMode::Continuous: return "continuous";
    case TerrainMode::Adaptive: return "adaptive";
    }
    return "?";
}

const char* toString(TessMetric metric) {
    switch (metric) {
    case TessMetric::ScreenEdge: return "screen";
    case TessMetric::Distance: return "distance";
    case TessMetric::Silhouette: return "silhouette";
    case TessMetric::HeightDetail: return "detail";
    }
    return "?";
}

// Parsing walks the enum through toString, so the names live in one place.
std::optional<TerrainMode> parseTerrainMode(std::string_view text) {
    for (TerrainMode mode : {TerrainMode::LowRes, TerrainMode::Continuous, TerrainMode::Adaptive})
        if (text == toString(mode)) return mode;
    return std::nullopt;
}

std::optional<TessMetric> parseTessMetric(std::string_view text) {
    for (TessMetric metric :
         {TessMetric::ScreenEdge, TessMetric::Distance, TessMetric::Silhouette, TessMetric::HeightDetail})
        if (text == toString(metric)) return metric;
    return std::nullopt;
}

} // namespace tessera::terrain
