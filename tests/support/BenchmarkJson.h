#pragma once
/// @file BenchmarkJson.h
/// Figures read back from the demo's --benchmark JSON report.

#include "JsonReader.h"
#include "TestFiles.h"

#include <cstdint>
#include <optional>
#include <string>

namespace tessera::test {

/// The median frame's clipping invocations (triangles the GPU clipped) of
/// pass `passName` in a --benchmark report; nullopt with `error` set when
/// the file or the pass's pipeline statistics are missing.
inline std::optional<uint64_t> passTriangles(const std::string& path, const std::string& passName,
                                             std::string& error) {
    JsonValue report;
    if (!parseJson(readTextFile(path), report, error)) return std::nullopt;
    const JsonValue* passes = report.find("passes");
    if (passes && passes->isArray())
        for (const JsonValue& pass : passes->array) {
            if (pass.stringAt("name") != passName) continue;
            const JsonValue* stats = pass.find("statsMedianFrame");
            if (auto n = stats ? stats->numberAt("clippingInvocations") : std::nullopt) return uint64_t(*n);
        }
    error = path + ": no pipeline statistics for pass " + passName;
    return std::nullopt;
}

} // namespace tessera::test
