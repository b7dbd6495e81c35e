#pragma once
/// @file BenchmarkJson.h
/// Figures read back from the demo's --benchmark JSON report.

#include "JsonFile.h"

#include <cstdint>
#include <optional>
#include <string>

namespace tessera::test {

/// The median frame's clipping invocations (triangles the GPU clipped) of
/// pass `passName` in a --benchmark report; nullopt with `error` set when
/// the file or the pass's pipeline statistics are missing.
inline std::optional<uint64_t> passTriangles(const std::string& path, const std::string& passName,
                                             std::string& error) {
    nlohmann::json report;
    if (!readJsonFile(path, report, error)) return std::nullopt;
    const nlohmann::json* passes = memberOf(report, "passes");
    if (passes && passes->is_array())
        for (const nlohmann::json& pass : *passes) {
            if (stringAt(pass, "name") != passName) continue;
            const nlohmann::json* stats = memberOf(pass, "statsMedianFrame");
            if (!stats) continue;
            // Triangles generated for the clipper (profiler::generatedPrimitivesOf):
            // a device may count none there for a mesh-shader pass.
            const auto clipped = numberAt(*stats, "clippingInvocations");
            const auto meshed = numberAt(*stats, "meshPrimitivesGenerated");
            if (clipped && *clipped > 0) return uint64_t(*clipped);
            if (meshed && *meshed > 0) return uint64_t(*meshed);
            if (clipped) return uint64_t(*clipped);
        }
    error = path + ": no pipeline statistics for pass " + passName;
    return std::nullopt;
}

} // namespace tessera::test
