#include "bench/CrowdBenchReport.h"

#include "bench/BenchText.h"
#include "tessera/core/JsonWriter.h"

namespace tessera::runtime {
namespace {

void writeSeries(JsonWriter& json, const char* key, const BenchSeries& series) {
    fixedObject(json, key, {{"median", series.median, 4}, {"mean", series.mean, 4}, {"max", series.max, 4}});
}

void writeOverlap(JsonWriter& json, const char* key, const crowd::OverlapReport& overlap) {
    fixedObject(json, key,
                {{"pairs", double(overlap.pairs), 0},
                 {"worst", overlap.worst, 4},
                 {"overlapping", double(overlap.overlapping), 0}});
}

void writeRun(JsonWriter& json, const CrowdBenchRun& r) {
    json.beginObject();
    json.keyValue("agents", r.agents);
    json.keyValue("layout", r.layout);
    fixed(json, "create_ms", r.createMs, 1);
    writeSeries(json, "step_ms", r.total);
    writeSeries(json, "fields_ms", r.fields);
    writeSeries(json, "avoidance_ms", r.avoidance);
    writeSeries(json, "integration_ms", r.integration);
    writeSeries(json, "wall_ms", r.wall);
    fixed(json, "bytes_per_agent", r.bytesPerAgent, 1);
    json.keyValue("agent_bytes", r.agentBytes);
    json.keyValue("field_bytes", r.fieldBytes);
    writeOverlap(json, "overlap_end", r.overlapEnd);
    writeOverlap(json, "overlap_worst_sampled", r.overlapWorst);
    json.keyValue("overlap_samples", r.overlapSamples);
    json.keyValue("arrivals", r.arrivals);
    json.keyValue("walking_end", r.walkingEnd);
    json.keyValue("stuck_end", r.stuckEnd);
    json.keyValue("stuck_max", r.stuckMax);
    fixed(json, "max_stuck_seconds", r.maxStuckSeconds, 2);
    json.keyValue("fleeing_end", r.fleeingEnd);
    json.keyValue("fleeing_max", r.fleeingMax);
    json.keyValue("unreachable_end", r.unreachableEnd);
    fixed(json, "field_tiles_solved_mean", r.fieldTilesSolvedMean, 2);
    json.keyValue("field_tiles_waiting_end", r.fieldTilesWaitingEnd);
    json.keyValue("impacts", r.impacts);
    fixed(json, "simulated_seconds", r.simulatedSeconds, 3);
    json.endObject();
}

} // namespace

std::string crowdBenchJson(const CrowdBenchSummary& s) {
    JsonWriter json(true);
    beginBenchDocument(json, "tessera-bench-crowd-sim", 1);
    json.keyValue("cpu_model", s.cpuModel);
    json.keyValue("cpu_cores", s.cpuCores);
    json.keyValue("threads", s.threads);
    json.keyValue("hardware_threads", s.hardwareThreads);
    json.keyValue("terrain", s.terrain);
    fixed(json, "terrain_width_m", s.terrainWidth, 2);
    fixed(json, "terrain_depth_m", s.terrainDepth, 2);
    fixed(json, "cell_size_m", s.cellSize, 3);
    fixed(json, "time_step_s", s.timeStep, 6);
    json.keyValue("warmup_steps", s.warmupSteps);
    json.keyValue("steps", s.steps);
    json.keyValue("overlap_every_steps", s.overlapEvery);
    fixed(json, "meteor_interval_s", s.meteorIntervalSeconds, 3);
    json.keyValue("seed", s.seed);
    json.keyValue("goal_groups", s.goalGroups);
    fixed(json, "goal_distance_m", s.goalDistance, 1);
    json.keyValue("arrival", "wander");
    fixed(json, "radius_min_m", s.radiusMin, 3);
    fixed(json, "radius_max_m", s.radiusMax, 3);
    fixed(json, "speed_min_m_per_s", s.speedMin, 3);
    fixed(json, "speed_max_m_per_s", s.speedMax, 3);
    json.key("runs");
    json.beginArray();
    for (const CrowdBenchRun& r : s.runs) writeRun(json, r);
    json.endArray();
    json.endObject();
    return std::move(json).take() + "\n";
}

std::string crowdBenchTable(const CrowdBenchSummary& s) {
    std::string text = format("crowd-sim on %s (%u cores), %u threads: %u warm-up + %u measured steps of %.1f ms, "
                              "a crater every %.0f s\n",
                              s.cpuModel.c_str(), s.cpuCores, s.threads, s.warmupSteps, s.steps, s.timeStep * 1000.0,
                              s.meteorIntervalSeconds);
    text += format("%8s %9s %9s %9s %9s %7s %9s %11s %8s %9s %8s %6s %8s %5s %7s %10s\n", "agents", "create ms",
                   "step med", "step mean", "step max", "fields", "avoidance", "integration", "B/agent", "field MiB",
                   "overlaps", "worst", "arrivals", "stuck", "fleeing", "tiles/step");
    for (const CrowdBenchRun& r : s.runs)
        text += format("%8u %9.0f %9.2f %9.2f %9.2f %7.2f %9.2f %11.2f %8.1f %9.1f %8u %6.2f %8llu %5u %7u %10.1f\n",
                       r.agents, r.createMs, r.total.median, r.total.mean, r.total.max, r.fields.median,
                       r.avoidance.median, r.integration.median, r.bytesPerAgent,
                       double(r.fieldBytes) / (1024.0 * 1024.0), r.overlapEnd.pairs, r.overlapWorst.worst,
                       static_cast<unsigned long long>(r.arrivals), r.stuckEnd, r.fleeingMax, r.fieldTilesSolvedMean);
    text += "(ms per step: median, mean and max of the total, medians of the phases; overlaps: overlapping pairs at "
            "the end; worst: the largest overlap sampled, a fraction of the sum of radii; fleeing: the most at once; "
            "tiles/step: field tiles solved per measured step)\n";
    return text;
}

} // namespace tessera::runtime
