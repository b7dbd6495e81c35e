#include "TerrainBenchReport.h"

#include "tessera/core/JsonWriter.h"

#include <cstdio>

namespace tessera::demo {

std::string terrainBenchJson(const std::vector<TerrainBenchRecord>& records) {
    JsonWriter json(true);
    json.beginArray();
    for (const auto& r : records) {
        json.beginObject();
        json.keyValue("backend", r.backend);
        json.keyValue("mode", r.mode);
        json.keyValue("view", r.view);
        json.keyValue("width", r.width);
        json.keyValue("height", r.height);
        json.keyValue("triangles", r.triangles);
        json.key("gpu_ms_median");
        json.valueFixed(r.gpuMsMedian, 6);
        json.key("gpu_ms_min");
        json.valueFixed(r.gpuMsMin, 6);
        json.key("gpu_ms_max");
        json.valueFixed(r.gpuMsMax, 6);
        json.keyValue("device", r.device);
        json.key("cpu_frame_ms_median");
        json.valueFixed(r.cpuFrameMsMedian, 6);
        json.keyValue("driver", r.driver);
        json.keyValue("patches", r.patches);
        json.keyValue("frames", r.frames);
        json.keyValue("metric", r.metric);
        json.keyValue("target_px", r.targetPixels);
        json.keyValue("continuous_level", r.continuousLevel);
        json.endObject();
    }
    json.endArray();
    return json.str() + "\n";
}

namespace {

std::string format(const char* pattern, auto... args) {
    char line[256];
    std::snprintf(line, sizeof line, pattern, args...);
    return line;
}

} // namespace

std::string terrainBenchTable(const std::vector<TerrainBenchRecord>& records) {
    std::string out = format("%-26s %-11s %-6s %-11s %-10s %10s %7s %9s %9s %9s %9s\n", "device", "backend", "view",
                             "mode", "metric", "triangles", "patches", "min ms", "median ms", "max ms", "cpu ms");
    for (const auto& r : records)
        out += format("%-26.26s %-11s %-6s %-11s %-10s %10llu %7u %9.3f %9.3f %9.3f %9.3f\n", r.device.c_str(),
                      r.backend.c_str(), r.view.c_str(), r.mode.c_str(), r.metric.c_str(),
                      static_cast<unsigned long long>(r.triangles), r.patches, r.gpuMsMin, r.gpuMsMedian, r.gpuMsMax,
                      r.cpuFrameMsMedian);
    out += "\nRatios to lowres in the same run (GPU median time, triangles):\n";
    for (const auto& base : records) {
        if (base.mode != "lowres" || base.gpuMsMedian <= 0.0 || base.triangles == 0) continue;
        for (const auto& r : records) {
            if (r.mode == "lowres" || r.device != base.device || r.backend != base.backend || r.view != base.view)
                continue;
            const std::string what = r.mode == "adaptive" ? "adaptive/" + r.metric : r.mode;
            out += format("  %-26.26s %-11s %-6s %-20s %6.2fx time, %8.1fx triangles\n", r.device.c_str(),
                          r.backend.c_str(), r.view.c_str(), what.c_str(), r.gpuMsMedian / base.gpuMsMedian,
                          double(r.triangles) / double(base.triangles));
        }
    }
    return out;
}

} // namespace tessera::demo
