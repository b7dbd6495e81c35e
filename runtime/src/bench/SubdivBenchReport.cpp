#include "bench/SubdivBenchReport.h"

#include "bench/BenchText.h"


namespace tessera::runtime {
namespace {

/// The base surface's row of the same backend and level, for the ratios.
const SubdivBenchRow* baseOf(const SubdivBenchSummary& summary, const SubdivBenchRow& row) {
    // The creature's rows compare with its Catmull-Clark row.
    if (row.variant.rfind("creature", 0) == 0) {
        for (const SubdivBenchRow& r : summary.rows)
            if (r.backend == row.backend && r.variant == "creature-cc") return &r;
        return nullptr;
    }
    for (const SubdivBenchRow& r : summary.rows)
        if (r.backend == row.backend && r.variant == "base" && (r.level == row.level || row.level == 0.0))
            return &r;
    return nullptr;
}

double ratio(double a, double b) {
    return b > 0.0 ? a / b : 0.0;
}

} // namespace

std::string subdivBenchJson(const SubdivBenchSummary& summary) {
    JsonWriter json;
    beginBenchDocument(json, "tessera-bench-subdiv", 1);
    json.keyValue("width", summary.width);
    json.keyValue("height", summary.height);
    json.keyValue("warmupFrames", summary.warmupFrames);
    json.keyValue("frames", summary.frames);
    json.key("surfaces");
    json.beginArray();
    for (const std::string& s : summary.surfaces) json.value(s);
    json.endArray();
    json.key("memory");
    json.beginObject();
    json.keyValue("coefficients", summary.memory.coefficients);
    json.keyValue("tileBytes", summary.memory.tileBytes);
    json.keyValue("denseMeshBytes", summary.memory.denseMeshBytes);
    json.keyValue("atlasBytes", summary.memory.atlasBytes);
    fixed(json, "denseMeshOverTiles", ratio(double(summary.memory.denseMeshBytes), double(summary.memory.tileBytes)), 2);
    fixed(json, "atlasOverTiles", ratio(double(summary.memory.atlasBytes), double(summary.memory.tileBytes)), 2);
    json.endObject();
    json.key("rows");
    json.beginArray();
    for (const SubdivBenchRow& row : summary.rows) {
        json.beginObject();
        json.keyValue("backend", row.backend);
        json.keyValue("device", row.device);
        json.keyValue("driver", row.driver);
        json.keyValue("variant", row.variant);
        fixed(json, "level", row.level, 2);
        fixedObject(json, "gpuMs", {{"median", row.gpuMsMedian, 4}, {"min", row.gpuMsMin, 4}, {"max", row.gpuMsMax, 4}});
        fixed(json, "gpuFrameMsMedian", row.gpuFrameMsMedian, 4);
        const SubdivBenchRow* base = baseOf(summary, row);
        fixed(json, "overBase", base ? ratio(row.gpuMsMedian, base->gpuMsMedian) : 0.0, 3);
        json.keyValue("frames", row.frames);
        json.keyValue("triangles", row.triangles);
        json.keyValue("clippingInvocations", row.clipped);
        json.keyValue("domains", row.domains);
        json.key("passes");
        json.beginObject();
        for (const auto& [name, ms] : row.passes) fixed(json, name, ms, 4);
        json.endObject();
        json.keyValue("trace", row.trace);
        json.endObject();
    }
    json.endArray();
    json.key("notes");
    json.beginArray();
    for (const std::string& note : summary.notes) json.value(note);
    json.endArray();
    json.endObject();
    return std::move(json).take();
}

std::string subdivBenchTable(const SubdivBenchSummary& summary) {
    std::string out = "Subdivision surfaces with analytic displacement (the second paper, section 7)\n";
    out += format("%-11s %-14s %6s %10s %8s %11s %9s\n", "backend", "variant", "level", "GPU ms", "x base",
                  "triangles", "domains");
    for (const SubdivBenchRow& row : summary.rows) {
        const SubdivBenchRow* base = baseOf(summary, row);
        const std::string level = row.level > 0.0 ? format("%.2f", row.level) : std::string("adapt");
        out += format("%-11s %-14s %6s %10.4f %8.3f %11llu %9u\n", row.backend.c_str(), row.variant.c_str(),
                      level.c_str(), row.gpuMsMedian, base ? ratio(row.gpuMsMedian, base->gpuMsMedian) : 0.0,
                      (unsigned long long)row.triangles, row.domains);
    }
    const SubdivMemory& m = summary.memory;
    out += format("\ndisplacement of %llu samples: tiles %.1f KiB; a dense mesh %.1f KiB (%.1fx); atlas maps %.1f KiB "
                  "(%.1fx)\n",
                  (unsigned long long)m.coefficients, m.tileBytes / 1024.0, m.denseMeshBytes / 1024.0,
                  ratio(double(m.denseMeshBytes), double(m.tileBytes)), m.atlasBytes / 1024.0,
                  ratio(double(m.atlasBytes), double(m.tileBytes)));
    for (const std::string& note : summary.notes) out += "note: " + note + "\n";
    return out;
}

} // namespace tessera::runtime
