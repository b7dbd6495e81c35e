#include "bench/TerrainBenchReport.h"

#include "bench/BenchText.h"
#include "tessera/core/JsonWriter.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

namespace tessera::runtime {

namespace {

bool sameRow(const TerrainBenchRecord& a, const TerrainBenchRecord& b) {
    return a.device == b.device && a.look == b.look && a.view == b.view && a.mode == b.mode && a.metric == b.metric &&
           a.targetPixels == b.targetPixels && a.continuousLevel == b.continuousLevel && a.tessMax == b.tessMax &&
           a.width == b.width && a.height == b.height;
}

double fragmentsPerPixel(const TerrainBenchRecord& r) {
    const double pixels = double(r.width) * double(r.height);
    return pixels > 0.0 ? double(r.fragmentShaderInvocations) / pixels : 0.0;
}

} // namespace

const TerrainBenchRecord* matchingRecord(const std::vector<TerrainBenchRecord>& records, const TerrainBenchRecord& r,
                                         const std::string& reference) {
    for (const auto& other : records)
        if (other.backend == reference && sameRow(other, r)) return &other;
    return nullptr;
}

std::string terrainBenchJson(const std::vector<TerrainBenchRecord>& records) {
    JsonWriter json(true);
    json.beginArray();
    for (const auto& r : records) {
        json.beginObject();
        json.keyValue("backend", r.backend);
        json.keyValue("mode", r.mode);
        json.keyValue("view", r.view);
        json.keyValue("look", r.look);
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
        // Levels and targets are floats: four decimals print 14.99, not
        // 14.989999771118164.
        json.key("target_px");
        json.valueFixed(r.targetPixels, 4);
        json.key("continuous_level");
        json.valueFixed(r.continuousLevel, 4);
        json.key("tess_max");
        json.valueFixed(r.tessMax, 4);
        json.keyValue("clipping_invocations", r.clippingInvocations);
        json.keyValue("vertex_shader_invocations", r.vertexShaderInvocations);
        json.keyValue("tess_evaluation_invocations", r.tessEvaluationInvocations);
        json.keyValue("geometry_shader_invocations", r.geometryShaderInvocations);
        json.keyValue("fragment_shader_invocations", r.fragmentShaderInvocations);
        json.key("fragments_per_pixel");
        json.valueFixed(fragmentsPerPixel(r), 4);
        json.keyValue("task_shader_invocations", r.taskShaderInvocations);
        json.keyValue("mesh_shader_invocations", r.meshShaderInvocations);
        json.keyValue("mesh_primitives", r.meshPrimitives);
        json.keyValue("intermediate_bytes", r.intermediateBytes);
        json.keyValue("trace", r.trace);
        // Flat keys keep every record a flat object (the format's promise);
        // the pass name sits inside the key.
        std::string names;
        for (const auto& p : r.passes) names += (names.empty() ? "" : ",") + p.name;
        json.keyValue("passes", names);
        for (const auto& p : r.passes) {
            const std::string prefix = "pass:" + p.name + ":";
            json.key(prefix + "gpu_ms_median");
            json.valueFixed(p.gpuMsMedian, 6);
            json.keyValue(prefix + "clipping_invocations", p.clippingInvocations);
            json.keyValue(prefix + "vertex_shader_invocations", p.vertexShaderInvocations);
            json.keyValue(prefix + "tess_evaluation_invocations", p.tessEvaluationInvocations);
            json.keyValue(prefix + "geometry_shader_invocations", p.geometryShaderInvocations);
            json.keyValue(prefix + "fragment_shader_invocations", p.fragmentShaderInvocations);
        }
        if (const TerrainBenchRecord* ref = matchingRecord(records, r, kComparisonReference)) {
            if (ref->gpuMsMedian > 0.0) {
                json.key("gpu_ms_vs_hulldomain");
                json.valueFixed(r.gpuMsMedian / ref->gpuMsMedian, 4);
            }
            if (ref->clippingInvocations > 0) {
                json.key("clipping_invocations_vs_hulldomain");
                json.valueFixed(double(r.clippingInvocations) / double(ref->clippingInvocations), 6);
            }
        }
        json.endObject();
    }
    json.endArray();
    return json.str() + "\n";
}

std::string terrainBenchTable(const std::vector<TerrainBenchRecord>& records) {
    std::string out = format("%-26s %-11s %-6s %-5s %-11s %-10s %10s %7s %9s %9s %9s %9s %7s\n", "device",
                             "backend", "view", "look", "mode", "metric", "triangles", "patches", "min ms", "median ms",
                             "max ms", "cpu ms", "frag/px");
    for (const auto& r : records)
        out += format("%-26.26s %-11s %-6s %-5s %-11s %-10s %10llu %7u %9.3f %9.3f %9.3f %9.3f %7.2f\n",
                      r.device.c_str(), r.backend.c_str(), r.view.c_str(), r.look.c_str(), r.mode.c_str(),
                      r.metric.c_str(), static_cast<unsigned long long>(r.triangles), r.patches, r.gpuMsMin,
                      r.gpuMsMedian, r.gpuMsMax, r.cpuFrameMsMedian, fragmentsPerPixel(r));
    out += "\nRatios to lowres in the same run (GPU median time, triangles):\n";
    for (const auto& base : records) {
        if (base.mode != "lowres" || base.gpuMsMedian <= 0.0 || base.triangles == 0) continue;
        for (const auto& r : records) {
            if (r.mode == "lowres" || r.device != base.device || r.backend != base.backend || r.view != base.view ||
                r.look != base.look)
                continue;
            const std::string what = r.mode == "adaptive" ? "adaptive/" + r.metric : r.mode;
            out += format("  %-26.26s %-11s %-6s %-20s %6.2fx time, %8.1fx triangles\n", r.device.c_str(),
                          r.backend.c_str(), r.view.c_str(), what.c_str(), r.gpuMsMedian / base.gpuMsMedian,
                          double(r.triangles) / double(base.triangles));
        }
    }
    // --look both: what the full look costs over the plain one, row by row
    // (docs/LOOKS.md: the budget is 25% of the terrain's frame time).
    bool header = false;
    for (const auto& full : records) {
        if (full.look != "full") continue;
        for (const auto& plain : records) {
            if (plain.look != "plain" || plain.backend != full.backend || plain.gpuMsMedian <= 0.0) continue;
            TerrainBenchRecord same = plain;
            same.look = full.look;
            if (!sameRow(same, full)) continue;
            if (!header) out += "\nThe full look's cost over the plain look (GPU median ms, CPU frame median ms):\n";
            header = true;
            const std::string what = full.mode == "adaptive" ? "adaptive/" + full.metric : full.mode;
            out += format("  %-26.26s %-11s %-6s %-20s %8.3f -> %8.3f ms (%+6.1f%%), cpu %8.3f -> %8.3f ms (%+6.1f%%)\n",
                          full.device.c_str(), full.backend.c_str(), full.view.c_str(), what.c_str(), plain.gpuMsMedian,
                          full.gpuMsMedian, 100.0 * (full.gpuMsMedian / plain.gpuMsMedian - 1.0),
                          plain.cpuFrameMsMedian, full.cpuFrameMsMedian,
                          plain.cpuFrameMsMedian > 0.0 ? 100.0 * (full.cpuFrameMsMedian / plain.cpuFrameMsMedian - 1.0)
                                                       : 0.0);
        }
    }
    return out;
}

} // namespace tessera::runtime

namespace tessera::runtime {

namespace {

std::string rowLabel(const TerrainBenchRecord& r) {
    if (r.mode == "adaptive") return "adaptive/" + r.metric;
    if (r.mode == "continuous") return format("continuous %.2f", r.continuousLevel);
    return r.mode;
}

std::string ratio(double value, double reference) {
    if (reference <= 0.0) return "-";
    return format("%.2fx", value / reference);
}

std::string kib(uint64_t bytes) {
    return format("%.1f", double(bytes) / 1024.0);
}

} // namespace

std::string backendComparisonTable(const std::vector<TerrainBenchRecord>& records,
                                   const std::vector<std::string>& notes) {
    std::string out = "\nBackends side by side (same run; triangles are the terrain pass's clipping invocations; "
                      "ratios to hulldomain):\n";
    out += format("%-26s %-6s %-20s %-11s %9s %7s %10s %7s %10s %10s %10s %12s\n", "device", "view", "mode", "backend",
                  "gpu ms", "x hd", "triangles", "x hd", "VS inv", "TES inv", "GS inv", "interm. KiB");
    // Rows in first-seen order of (device, view, mode), each with every backend.
    std::vector<const TerrainBenchRecord*> seen;
    for (const auto& r : records) {
        if (std::any_of(seen.begin(), seen.end(), [&](const TerrainBenchRecord* s) { return sameRow(*s, r); }))
            continue;
        seen.push_back(&r);
    }
    for (const TerrainBenchRecord* row : seen) {
        const TerrainBenchRecord* ref = matchingRecord(records, *row, kComparisonReference);
        for (const auto& r : records) {
            if (!sameRow(r, *row)) continue;
            out +=
                format("%-26.26s %-6s %-20s %-11s %9.3f %7s %10llu %7s %10llu %10llu %10llu %12s\n", r.device.c_str(),
                       r.view.c_str(), rowLabel(r).c_str(), r.backend.c_str(), r.gpuMsMedian,
                       ref ? ratio(r.gpuMsMedian, ref->gpuMsMedian).c_str() : "-",
                       static_cast<unsigned long long>(r.clippingInvocations),
                       ref ? ratio(double(r.clippingInvocations), double(ref->clippingInvocations)).c_str() : "-",
                       static_cast<unsigned long long>(r.vertexShaderInvocations),
                       static_cast<unsigned long long>(r.tessEvaluationInvocations),
                       static_cast<unsigned long long>(r.geometryShaderInvocations), kib(r.intermediateBytes).c_str());
        }
    }
    out += "\nGPU ms per pass (median of the measured frames):\n";
    for (const TerrainBenchRecord* row : seen) {
        for (const auto& r : records) {
            if (!sameRow(r, *row)) continue;
            std::string line = format("  %-6s %-20s %-11s", r.view.c_str(), rowLabel(r).c_str(), r.backend.c_str());
            for (const auto& p : r.passes) line += format("  %s %.3f", p.name.c_str(), p.gpuMsMedian);
            out += line + "\n";
        }
    }
    // Mismatched triangle counts are a bug in a backend: say so where it shows.
    for (const auto& r : records) {
        const TerrainBenchRecord* ref = matchingRecord(records, r, kComparisonReference);
        if (ref && &r != ref && r.clippingInvocations != ref->clippingInvocations)
            out += format("note: %s %s %s: %llu triangles, hulldomain %llu (the same levels should give the same "
                          "triangles)\n",
                          r.backend.c_str(), r.view.c_str(), rowLabel(r).c_str(),
                          static_cast<unsigned long long>(r.clippingInvocations),
                          static_cast<unsigned long long>(ref->clippingInvocations));
    }
    for (const auto& note : notes) out += "note: " + note + "\n";
    return out;
}

} // namespace tessera::runtime
