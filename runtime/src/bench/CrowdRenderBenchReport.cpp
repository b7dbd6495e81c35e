#include "bench/CrowdRenderBenchReport.h"

#include "bench/BenchText.h"
#include "tessera/core/JsonWriter.h"

namespace tessera::runtime {
namespace {

constexpr const char* kTierNames[lod::kTierCount] = {"near", "middle", "far", "impostor"};

void writeSeries(JsonWriter& json, const char* key, const BenchSeries& series) {
    fixedObject(
        json, key,
        {{"median", series.median, 4}, {"mean", series.mean, 4}, {"min", series.min, 4}, {"max", series.max, 4}});
}

/// The row of `backend` with `agents` agents, or null.
const CrowdRenderRow* find(const CrowdRenderSummary& s, const std::string& backend, uint32_t agents) {
    for (const CrowdRenderRow& r : s.rows)
        if (r.backend == backend && r.agents == agents) return &r;
    return nullptr;
}

double ratio(double a, double b) {
    return b > 0.0 ? a / b : 0.0;
}

void writeRow(JsonWriter& json, const CrowdRenderSummary& s, const CrowdRenderRow& r) {
    json.beginObject();
    json.keyValue("backend", r.backend);
    json.keyValue("device", r.device);
    json.keyValue("driver", r.driver);
    json.keyValue("agents", r.agents);
    json.keyValue("frames", r.frames);
    json.keyValue("camera", r.camera);
    writeSeries(json, "gpu_frame_ms", r.gpuFrame);
    writeSeries(json, "cpu_frame_ms", r.cpuFrame);
    writeSeries(json, "simulation_ms", r.simulation);
    writeSeries(json, "lod_ms", r.lod);
    writeSeries(json, "instances_ms", r.instances);
    json.key("passes");
    json.beginObject();
    for (const auto& [name, ms] : r.passes) fixed(json, name, ms, 4);
    json.endObject();
    fixedObject(json, "crowd_gpu_ms",
                {{"cull_bin", r.cullBinMs, 4},
                 {"skin", r.skinMs, 4},
                 {"near", r.tierMs[0], 4},
                 {"middle", r.tierMs[1], 4},
                 {"far", r.tierMs[2], 4},
                 {"impostor", r.tierMs[3], 4}});
    fixed(json, "terrain_gpu_ms", r.terrainMs, 4);
    json.key("tiers");
    json.beginObject();
    for (uint32_t t = 0; t < lod::kTierCount; ++t)
        fixedObject(json, kTierNames[t],
                    {{"instances", r.tierInstances[t], 1}, {"triangles", r.tierTriangles[t], 0}, {"hidden", r.tierHidden[t], 1}});
    json.endObject();
    json.keyValue("crowd_bytes", r.crowdBytes);
    fixed(json, "gpu_bytes_per_agent", r.agents ? double(r.crowdBytes) / r.agents : 0.0, 1);
    json.key("suspect_passes");
    json.beginArray();
    for (const std::string& name : r.suspectPasses) json.value(name);
    json.endArray();
    if (const CrowdRenderRow* ref = find(s, "hulldomain", r.agents))
        fixedObject(json, "ratio_to_hulldomain",
                    {{"gpu_frame", ratio(r.gpuFrame.median, ref->gpuFrame.median), 3},
                     {"cpu_frame", ratio(r.cpuFrame.median, ref->cpuFrame.median), 3}});
    if (const CrowdRenderRow* alone = find(s, r.backend, 0); alone && r.agents)
        fixedObject(json, "ratio_to_terrain_alone",
                    {{"gpu_frame", ratio(r.gpuFrame.median, alone->gpuFrame.median), 3},
                     {"cpu_frame", ratio(r.cpuFrame.median, alone->cpuFrame.median), 3}});
    json.keyValue("trace", r.trace);
    json.endObject();
}

} // namespace

std::string crowdRenderBenchJson(const CrowdRenderSummary& s) {
    JsonWriter json(true);
    beginBenchDocument(json, "tessera-bench-crowd", 1);
    json.keyValue("width", s.width);
    json.keyValue("height", s.height);
    json.keyValue("warmup_frames", s.warmupFrames);
    json.keyValue("frames", s.frames);
    json.keyValue("meteors", s.meteors);
    json.keyValue("camera", s.camera);
    json.keyValue("terrain", s.terrain);
    json.key("notes");
    json.beginArray();
    for (const std::string& note : s.notes) json.value(note);
    json.endArray();
    json.key("rows");
    json.beginArray();
    for (const CrowdRenderRow& r : s.rows) writeRow(json, s, r);
    json.endArray();
    json.endObject();
    return json.str() + "\n";
}

std::string crowdRenderBenchTable(const CrowdRenderSummary& s) {
    std::string out = format("crowd rendering, %ux%u, %u measured frames after %u, camera %s\n", s.width, s.height,
                             s.frames, s.warmupFrames, s.camera.c_str());
    out += format("%-10s %7s | %8s %8s %8s | %7s %6s %7s %7s %7s %7s %8s | %7s %7s %7s %7s | %10s %10s %10s | "
                  "%8s | %s\n",
                  "backend", "agents", "GPU ms", "CPU ms", "sim ms", "cull+bin", "skin", "near", "middle", "far",
                  "imp", "terrain", "n near", "n mid", "n far", "n imp", "tri near", "tri mid", "tri far", "B/agent",
                  "hidden near/mid/far/imp");
    for (const CrowdRenderRow& r : s.rows) {
        out += format("%-10s %7u | %8.3f %8.3f %8.3f | %7.3f %6.3f %7.3f %7.3f %7.3f %7.3f %8.3f | %7.0f %7.0f %7.0f "
                      "%7.0f | %10.0f %10.0f %10.0f | %8.1f | %.0f/%.0f/%.0f/%.0f\n",
                      r.backend.c_str(), r.agents, r.gpuFrame.median, r.cpuFrame.median, r.simulation.median,
                      r.cullBinMs, r.skinMs, r.tierMs[0], r.tierMs[1], r.tierMs[2], r.tierMs[3], r.terrainMs,
                      r.tierInstances[0], r.tierInstances[1], r.tierInstances[2], r.tierInstances[3],
                      r.tierTriangles[0], r.tierTriangles[1], r.tierTriangles[2],
                      r.agents ? double(r.crowdBytes) / r.agents : 0.0, r.tierHidden[0], r.tierHidden[1],
                      r.tierHidden[2], r.tierHidden[3]);
        if (!r.suspectPasses.empty()) {
            std::string names;
            for (const std::string& n : r.suspectPasses) names += (names.empty() ? "" : ", ") + n;
            out += "           GPU time not trusted (lavapipe's timestamps miss or carry rasterisation): " + names + "\n";
        }
    }
    out += "ratios (GPU frame, CPU frame): to hulldomain at the same size; to the backend's terrain alone\n";
    for (const CrowdRenderRow& r : s.rows) {
        if (r.agents == 0) continue;
        const CrowdRenderRow* ref = find(s, "hulldomain", r.agents);
        const CrowdRenderRow* alone = find(s, r.backend, 0);
        out += format("%-10s %7u   vs hulldomain %5.2fx %5.2fx   vs terrain alone %5.2fx %5.2fx\n", r.backend.c_str(),
                      r.agents, ref ? ratio(r.gpuFrame.median, ref->gpuFrame.median) : 0.0,
                      ref ? ratio(r.cpuFrame.median, ref->cpuFrame.median) : 0.0,
                      alone ? ratio(r.gpuFrame.median, alone->gpuFrame.median) : 0.0,
                      alone ? ratio(r.cpuFrame.median, alone->cpuFrame.median) : 0.0);
    }
    for (const std::string& note : s.notes) out += "note: " + note + "\n";
    return out;
}

} // namespace tessera::runtime
