#include "bench/CharacterBenchReport.h"

#include "bench/BenchText.h"
#include "tessera/core/JsonWriter.h"

#include <cstdio>

namespace tessera::runtime {
namespace {

double ratio(double value, double reference) {
    return reference > 0.0 ? value / reference : 0.0;
}

// Table 1 compares the paper's pair: the cage and the displacement map
// (the normal map is reported beside it; the paper's table leaves it out).
uint64_t cageAndDisplacement(const CharacterAssetFigures& a) {
    return a.cageBytes + a.displacementBytes;
}

double mib(uint64_t bytes) {
    return double(bytes) / (1024.0 * 1024.0);
}

// The keys every per-asset object starts with.
void writeAssetCage(JsonWriter& json, const CharacterAssetFigures& a) {
    json.keyValue("asset", a.name);
    json.keyValue("cage_vertices", a.cageVertices);
    json.keyValue("cage_triangles", a.cageTriangles);
}

void writeRow(JsonWriter& json, const CharacterBenchRow& r, const std::vector<CharacterBenchRow>& rows) {
    json.beginObject();
    json.keyValue("backend", r.backend);
    json.keyValue("path", r.path);
    fixed(json, "level", r.level, 4);
    json.keyValue("device", r.device);
    json.keyValue("driver", r.driver);
    json.keyValue("frames", r.frames);
    fixed(json, "character_gpu_ms_median", r.characterMsMedian, 6);
    fixed(json, "character_gpu_ms_min", r.characterMsMin, 6);
    fixed(json, "character_gpu_ms_max", r.characterMsMax, 6);
    fixed(json, "gpu_frame_ms_median", r.gpuFrameMsMedian, 6);
    json.keyValue("characters_drawn", r.charactersDrawn);
    json.keyValue("cage_triangles", r.cageTriangles);
    json.keyValue("triangles", r.triangles);
    fixed(json, "amplification", ratio(double(r.triangles), double(r.cageTriangles)), 4);
    json.keyValue("clipping_invocations", r.clippingInvocations);
    json.keyValue("intermediate_bytes", r.intermediateBytes);
    json.keyValue("trace", r.trace);
    std::string names;
    for (const auto& [name, ms] : r.passes) names += (names.empty() ? "" : ",") + name;
    json.keyValue("passes", names);
    for (const auto& [name, ms] : r.passes) {
        json.key("pass:" + name + ":gpu_ms_median");
        json.valueFixed(ms, 6);
    }
    if (const CharacterBenchRow* single = r.path == "two-pass" ? singlePassPartner(rows, r) : nullptr) {
        fixed(json, "single_pass_gpu_ms_median", single->characterMsMedian, 6);
        fixed(json, "single_over_two_pass", ratio(single->characterMsMedian, r.characterMsMedian), 4);
        fixed(json, "two_pass_faster_percent",
              100.0 * ratio(single->characterMsMedian - r.characterMsMedian, single->characterMsMedian), 2);
    }
    json.endObject();
}

void writeAmplification(JsonWriter& json, const CharacterBenchSummary& s) {
    json.beginObject();
    json.keyValue("paper_cage_triangles", kPaperCageTriangles);
    json.keyValue("paper_triangles", kPaperTessellatedTriangles);
    fixed(json, "paper_amplification", kPaperTessellatedTriangles / kPaperCageTriangles, 2);
    fixed(json, "paper_level", s.paperLevel, 4);
    fixed(json, "paper_level_amplification", s.paperLevelAmplification, 2);
    fixed(json, "shared_level", s.sharedLevel, 4);
    json.key("characters");
    json.beginArray();
    for (const auto& a : s.assets) {
        json.beginObject();
        writeAssetCage(json, a);
        json.keyValue("triangles_per_cage_triangle", a.trianglesPerCageTriangle);
        json.keyValue("triangles_at_shared_level", a.tessellatedTriangles);
        json.keyValue("triangles_at_paper_level", a.paperLevelTriangles);
        json.endObject();
    }
    json.endArray();
    json.endObject();
}

void writeTable1(JsonWriter& json, const CharacterBenchSummary& s) {
    json.beginObject();
    fixed(json, "level", s.tableLevel, 4);
    json.keyValue("cage_vertex_bytes", kCageVertexBytes);
    json.keyValue("compressed_vertex_bytes", kCompressedVertexBytes);
    json.keyValue("index_bytes_per_triangle", kTriangleIndexBytes);
    json.keyValue("dense_vertex_bytes", kCageVertexBytes);
    json.keyValue("dense_vertex_format", "position, normal, tangent, uv, 4 joints, 4 weights (the cage's 80 B "
                                         "vertex); vertices = triangles / 2; 32-bit indices");
    json.keyValue("paper_cage_and_displacement_bytes", kPaperTable1CageBytes);
    json.keyValue("paper_dense_bytes", kPaperTable1DenseBytes);
    fixed(json, "paper_dense_over_cage_and_displacement", kPaperTable1DenseBytes / kPaperTable1CageBytes, 2);
    json.key("characters");
    json.beginArray();
    for (const auto& a : s.assets) {
        json.beginObject();
        writeAssetCage(json, a);
        json.keyValue("cage_bytes", a.cageBytes);
        json.keyValue("compressed_cage_bytes", a.compressedCageBytes);
        json.keyValue("displacement_map_width", a.displacementWidth);
        json.keyValue("displacement_map_height", a.displacementHeight);
        json.keyValue("displacement_map_bytes", a.displacementBytes);
        json.keyValue("normal_map_bytes", a.normalMapBytes);
        json.keyValue("cage_and_displacement_bytes", cageAndDisplacement(a));
        json.keyValue("cage_and_maps_bytes", cageAndDisplacement(a) + a.normalMapBytes);
        json.keyValue("dense_triangles", a.denseTriangles);
        json.keyValue("dense_vertices", a.denseVertices);
        json.keyValue("dense_bytes", a.denseBytes);
        fixed(json, "dense_over_cage_and_displacement", ratio(double(a.denseBytes), double(cageAndDisplacement(a))), 2);
        if (a.sculpt) {
            json.keyValue("sculpt_report", a.sculpt->file);
            json.keyValue("sculpt_triangles", a.sculpt->sculptTriangles);
            json.keyValue("sculpt_vertices", a.sculpt->sculptVertices);
            json.keyValue("sculpt_dense_bytes", a.sculpt->denseMeshBytes);
            json.keyValue("sculpt_dense_formula", a.sculpt->denseMeshFormula);
            fixed(json, "sculpt_over_cage_and_displacement",
                  ratio(double(a.sculpt->denseMeshBytes), double(cageAndDisplacement(a))), 2);
        }
        json.endObject();
    }
    json.endArray();
    json.endObject();
}

void writeCompression(JsonWriter& json, const CharacterBenchSummary& s) {
    json.beginArray();
    for (const auto& a : s.assets) {
        json.beginObject();
        json.keyValue("asset", a.name);
        json.keyValue("vertices_measured", a.error.vertexCount);
        fixed(json, "max_position_error_relative", a.error.maxPositionError, 9);
        fixed(json, "max_normal_angle_deg", a.error.maxNormalAngleDeg, 6);
        fixed(json, "max_tangent_angle_deg", a.error.maxTangentAngleDeg, 6);
        fixed(json, "max_uv_error", a.error.maxUvError, 9);
        json.endObject();
    }
    json.endArray();
}

} // namespace

const CharacterBenchRow* singlePassPartner(const std::vector<CharacterBenchRow>& rows,
                                           const CharacterBenchRow& twoPass) {
    for (const auto& r : rows)
        if (r.path == "single-pass" && r.backend == twoPass.backend && r.device == twoPass.device &&
            r.level == twoPass.level)
            return &r;
    return nullptr;
}

std::string characterBenchJson(const CharacterBenchSummary& s) {
    JsonWriter json(true);
    beginBenchDocument(json, "tessera-bench-characters", 1);
    json.keyValue("width", s.width);
    json.keyValue("height", s.height);
    json.keyValue("warmup_frames", s.warmupFrames);
    json.keyValue("frames", s.frames);
    json.keyValue("characters_per_frame", s.crowdMembers);
    fixed(json, "pose_seconds", s.poseSeconds, 4);
    fixed(json, "shared_level", s.sharedLevel, 4);
    json.key("timing");
    json.beginArray();
    for (const auto& r : s.rows) writeRow(json, r, s.rows);
    json.endArray();
    json.key("amplification");
    writeAmplification(json, s);
    json.key("table1");
    writeTable1(json, s);
    json.key("compression_error");
    writeCompression(json, s);
    json.key("notes");
    json.beginArray();
    for (const auto& note : s.notes) json.value(note);
    json.endArray();
    json.endObject();
    return json.str() + "\n";
}

std::string characterBenchTable(const CharacterBenchSummary& s) {
    std::string out = format("\nTwo-pass compressed vs single-pass: %u characters posed at t = %.2f s, %ux%u, "
                             "median GPU ms of the character passes over %u frames (after %u warm-up)\n",
                             s.crowdMembers, s.poseSeconds, s.width, s.height, s.frames, s.warmupFrames);
    out += format("%-26s %-11s %6s %10s %9s %9s %11s %8s %10s %10s %7s\n", "device", "backend", "level", "two-pass",
                  "skin", "tess", "single-pass", "1p / 2p", "2p faster", "triangles", "x cage");
    for (const auto& r : s.rows) {
        if (r.path != "two-pass") continue;
        double skin = 0.0, tess = 0.0;
        for (const auto& [name, ms] : r.passes) {
            if (name == "character.skin") skin = ms;
            if (name == "character.tessellate") tess = ms;
        }
        const CharacterBenchRow* single = singlePassPartner(s.rows, r);
        const double one = single ? single->characterMsMedian : 0.0;
        out += format("%-26.26s %-11s %6.2f %10.3f %9.3f %9.3f %11.3f %7.2fx %9.1f%% %10llu %6.1fx\n", r.device.c_str(),
                      r.backend.c_str(), r.level, r.characterMsMedian, skin, tess, one, ratio(one, r.characterMsMedian),
                      100.0 * ratio(one - r.characterMsMedian, one), static_cast<unsigned long long>(r.triangles),
                      ratio(double(r.triangles), double(r.cageTriangles)));
    }
    out += "(paper: about 25% faster two-pass with compression)\n";

    out += format("\nAmplification per character (paper: %.0f cage triangles -> %.1fM, %.0fx; level %.2f gives "
                  "%.0fx here):\n",
                  kPaperCageTriangles, kPaperTessellatedTriangles / 1e6,
                  kPaperTessellatedTriangles / kPaperCageTriangles, s.paperLevel, s.paperLevelAmplification);
    out += format("%-22s %8s %12s %7s %16s\n", "asset", "cage", "at shared", "x", "at paper level");
    for (const auto& a : s.assets)
        out += format("%-22.22s %8u %12llu %6.1fx %16llu\n", a.name.c_str(), a.cageTriangles,
                      static_cast<unsigned long long>(a.tessellatedTriangles),
                      ratio(double(a.tessellatedTriangles), double(a.cageTriangles)),
                      static_cast<unsigned long long>(a.paperLevelTriangles));

    out += format("\nTable 1 at level %.2f (MiB; cage = 80 B vertices + 32-bit indices, dense = the tessellated "
                  "triangle count with cage-format vertices, V = T/2; paper: 10 MB vs 450 MB, 45x):\n",
                  s.tableLevel);
    out += format("%-22s %8s %9s %9s %9s %10s %11s %9s %11s %7s\n", "asset", "cage", "16B cage", "displace", "normal",
                  "cage+disp", "dense tris", "dense", "x cage+disp", "sculpt");
    for (const auto& a : s.assets)
        out += format(
            "%-22.22s %8.3f %9.3f %9.3f %9.3f %10.3f %11llu %9.1f %10.1fx %7s\n", a.name.c_str(), mib(a.cageBytes),
            mib(a.compressedCageBytes), mib(a.displacementBytes), mib(a.normalMapBytes), mib(cageAndDisplacement(a)),
            static_cast<unsigned long long>(a.denseTriangles), mib(a.denseBytes),
            ratio(double(a.denseBytes), double(cageAndDisplacement(a))),
            a.sculpt ? format("%.1fx", ratio(double(a.sculpt->denseMeshBytes), double(cageAndDisplacement(a)))).c_str()
                     : "-");
    for (const auto& a : s.assets)
        if (a.sculpt)
            out += format("  %s sculpt: %llu triangles, %.1f MiB (%s)\n", a.name.c_str(),
                          static_cast<unsigned long long>(a.sculpt->sculptTriangles), mib(a.sculpt->denseMeshBytes),
                          a.sculpt->denseMeshFormula.c_str());

    out += "\nCompression error of the 128-bit vertex over every clip (position relative to the box's largest "
           "extent):\n";
    out +=
        format("%-22s %10s %12s %11s %12s %10s\n", "asset", "vertices", "position", "normal deg", "tangent deg", "uv");
    for (const auto& a : s.assets)
        out +=
            format("%-22.22s %10u %12.3e %11.4f %12.4f %10.2e\n", a.name.c_str(), a.error.vertexCount,
                   a.error.maxPositionError, a.error.maxNormalAngleDeg, a.error.maxTangentAngleDeg, a.error.maxUvError);
    for (const auto& note : s.notes) out += "note: " + note + "\n";
    return out;
}

} // namespace tessera::runtime
