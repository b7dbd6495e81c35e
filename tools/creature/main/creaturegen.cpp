// tessera-creaturegen: generates a Froblin-like creature, bakes its
// displacement and normal maps and writes it as a .glb (the paper's content
// pipeline: sculpt -> cage -> GPUMeshMapper -> game asset).
// Exit status: 0 on success, 1 when a stage fails, 2 on a bad command line.

#include "CreatureGenOptions.h"
#include "GlbMeshBytes.h"

#include "creature/CreatureGenerator.h"
#include "creature/DisplacementBaker.h"
#include "creature/GlbExporter.h"
#include "creature/SubdivBaker.h"
#include "tessera/assets/GltfLoader.h"
#include "tessera/core/ProgressBar.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <system_error>

using namespace tessera;
using namespace tessera::creature;

namespace {

// Where each stage sits in the overall bar (start, width).
float overall(const char* stage, float f) {
    if (std::strcmp(stage, "shape") == 0) return 0.00f + 0.08f * f;
    if (std::strcmp(stage, "cage") == 0) return 0.08f + 0.07f * f;
    if (std::strcmp(stage, "sculpt") == 0) return 0.15f + 0.20f * f;
    if (std::strcmp(stage, "texture") == 0) return 0.35f + 0.05f * f;
    if (std::strcmp(stage, "bake") == 0) return 0.40f + 0.50f * f;
    if (std::strcmp(stage, "export") == 0) return 0.90f + 0.04f * f;
    return 0.94f + 0.06f * f;  // subdiv
}

// The Catmull-Clark version (docs/SUBDIV.md, "The Froblin as a
// Catmull-Clark surface"): baked on the cage as the .glb holds it (Draco
// moves positions and reorders vertices), read back through the engine's
// own loader, because that is the cage the demo welds and animates.
Result<SubdivBakeResult> bakeSubdivTiles(const std::filesystem::path& glb, const SculptMesh& sculpt,
                                         uint64_t planarTexels, const character::CageMesh& cage) {
    auto loaded = assets::loadCharacter(glb);
    if (!loaded) return loaded.error();
    double area = 0.0;
    for (uint32_t t = 0; t < cage.triangleCount(); ++t) {
        const glm::vec3 a = cage.vertices[cage.indices[3 * t]].position;
        const glm::vec3 b = cage.vertices[cage.indices[3 * t + 1]].position;
        const glm::vec3 c = cage.vertices[cage.indices[3 * t + 2]].position;
        area += 0.5 * double(glm::length(glm::cross(b - a, c - a)));
    }
    SubdivBakeOptions options;
    // As much detail per area as the planar map holds.
    options.texelsPerArea = area > 0.0 ? double(planarTexels) / area : 0.0;
    return bakeSubdivDisplacement(*loaded, sculpt, options, glb.filename().string());
}

nlohmann::json errorJson(const SurfaceError& e) {
    return {{"rms", e.rms}, {"max", e.max}, {"samples", e.samples}, {"unmeasured", e.unmeasured}};
}

// Table 1's dense mesh: the paper's 32-byte vertex (position, normal, uv
// as floats) for each sculpt vertex plus three 32-bit indices a triangle.
uint64_t denseMeshBytes(const SculptMesh& sculpt) {
    return static_cast<uint64_t>(sculpt.positions.size()) * 32u + static_cast<uint64_t>(sculpt.triangleCount()) * 12u;
}

} // namespace

int main(int argc, char** argv) {
    auto parsed = parseCreatureGenOptions(argc, argv);
    if (!parsed) {
        std::fprintf(stderr, "tessera-creaturegen: %s\n", parsed.error().message.c_str());
        return 2;
    }
    const CreatureGenOptions& o = *parsed;
    if (o.help) {
        std::fputs(creatureGenUsage().c_str(), stdout);
        return 0;
    }
    for (const auto& file : {o.out, o.report}) {
        std::error_code ec;
        if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path(), ec);
        if (ec) {
            std::fprintf(stderr, "tessera-creaturegen: %s: cannot create folder: %s\n",
                         file.parent_path().string().c_str(), ec.message().c_str());
            return 1;
        }
    }

    const auto start = std::chrono::steady_clock::now();
    // A log gets one line per stage.
    core::ProgressBar bar(stderr, "tessera-creaturegen", o.quiet);
    auto show = [&](const char* stage, float f) { bar.update(stage, overall(stage, f)); };
    CreatureOptions creatureOptions;
    creatureOptions.seed = o.seed;
    creatureOptions.sculptTriangles = o.sculptTriangles;
    creatureOptions.cageTriangles = o.cageTriangles;
    Creature creature = generateCreature(creatureOptions, show);

    BakeOptions bakeOptions;
    bakeOptions.resolution = o.mapSize;
    auto bakedOrError = bakeDisplacement(creature.asset.cage, creature.sculpt, bakeOptions,
                                         [&](float f) { show("bake", f); });
    if (!bakedOrError) {
        bar.finish();
        std::fprintf(stderr, "tessera-creaturegen: %s\n", bakedOrError.error().message.c_str());
        return 1;
    }
    const BakeResult& baked = *bakedOrError;
    creature.asset.displacement = baked.displacement;
    creature.asset.normalMap = baked.normalMap;

    // Export both ways: one is the output, the other only measured.
    show("export", 0.0f);
    ExportOptions exportOptions;
    exportOptions.draco = !o.uncompressed;
    if (auto s = exportGlb(creature.asset, o.out, exportOptions); !s) {
        std::fprintf(stderr, "tessera-creaturegen: %s\n", s.error().message.c_str());
        return 1;
    }
    std::filesystem::path other = o.out;
    other += ".measure.glb";
    ExportOptions otherOptions = exportOptions;
    otherOptions.draco = !exportOptions.draco;
    Status otherOk = exportGlb(creature.asset, other, otherOptions);
    auto mainBytes = measureGlbMeshBytes(o.out);
    auto otherBytes = otherOk ? measureGlbMeshBytes(other) : Result<uint64_t>(otherOk.error());
    std::error_code ignored;
    std::filesystem::remove(other, ignored);
    if (!mainBytes || !otherBytes) {
        std::fprintf(stderr, "tessera-creaturegen: %s\n",
                     (!mainBytes ? mainBytes.error() : otherBytes.error()).message.c_str());
        return 1;
    }
    show("export", 1.0f);
    show("subdiv", 0.0f);
    std::filesystem::path tilesFile = o.out;
    tilesFile.replace_extension(".cctiles");
    auto subdivBaked = bakeSubdivTiles(o.out, creature.sculpt, baked.stats.texelsCovered, creature.asset.cage);
    Status tilesWritten = subdivBaked ? subdiv::writeCageTiles(tilesFile, subdivBaked->file) : Status(subdivBaked.error());
    if (!tilesWritten) {
        bar.finish();
        std::fprintf(stderr, "tessera-creaturegen: %s\n", tilesWritten.error().message.c_str());
        return 1;
    }
    const SubdivBakeStats& cc = subdivBaked->stats;
    show("subdiv", 1.0f);
    bar.finish();
    uint64_t dracoBytes = o.uncompressed ? *otherBytes : *mainBytes;
    uint64_t plainBytes = o.uncompressed ? *mainBytes : *otherBytes;

    const auto& cage = creature.asset.cage;
    const auto& disp = *creature.asset.displacement;
    uint64_t mapBytes = static_cast<uint64_t>(disp.image.width) * disp.image.height * 2u;
    uint64_t normalBytes = static_cast<uint64_t>(baked.normalMap.width) * baked.normalMap.height * 4u;
    nlohmann::json report = {
        {"seed", o.seed},
        {"file", o.out.filename().string()},
        {"cage_triangles", cage.triangleCount()},
        {"cage_vertices", cage.vertices.size()},
        {"cage_bytes_uncompressed", plainBytes},
        {"cage_bytes_draco", dracoBytes},
        {"sculpt_triangles", creature.sculpt.triangleCount()},
        {"sculpt_vertices", creature.sculpt.positions.size()},
        {"map_size", disp.image.width},
        {"displacement_map_bytes", mapBytes},
        {"normal_map_bytes", normalBytes},
        {"dense_mesh_bytes", denseMeshBytes(creature.sculpt)},
        {"dense_mesh_formula", "sculpt_vertices * 32 + sculpt_triangles * 12"},
        {"displacement_scale", disp.scale},
        {"displacement_bias", disp.bias},
        {"texels_covered", baked.stats.texelsCovered},
        {"misses", baked.stats.misses},
    };
    report["subdiv"] = {
        {"file", tilesFile.filename().string()},
        {"file_bytes", cc.fileBytes},
        {"control_vertices", cc.controlVertices},
        {"ptex_faces", cc.ptexFaces},
        {"patches", cc.patches},
        {"tile_log2_size", cc.tileLog2Size},
        {"coefficients", cc.coefficients},
        {"misses", cc.misses},
        {"misses_from_neighbours", cc.missesFromNeighbours},
        {"misses_zero", cc.missesZero},
        {"conversion_rounds", cc.conversionRounds},
        {"conversion_converged", cc.converged},
        {"error_subdiv", errorJson(cc.subdiv)},
        {"error_subdiv_undisplaced", errorJson(cc.subdivBase)},
        {"error_planar", errorJson(cc.planar)},
        {"error_note", "distance along the displacement direction to the sculpt, model units (metres)"},
    };
    if (creature.far) {
        // The far LOD mesh (docs/CHARACTERS.md, "The far mesh").
        report["far_triangles"] = creature.far->mesh.triangleCount();
        report["far_vertices"] = creature.far->mesh.vertices.size();
        report["far_method"] = character::farMeshMethodName(creature.far->method);
        report["far_error_relative"] = creature.far->relativeError;
        report["far_error"] = creature.far->absoluteError;
        report["far_seam_triangles"] = creature.far->seamTriangles;
    }
    if (!o.report.empty()) {
        std::ofstream out(o.report);
        out << report.dump(2) << "\n";
        if (!out) {
            std::fprintf(stderr, "tessera-creaturegen: %s: cannot write the report\n", o.report.string().c_str());
            return 1;
        }
    }
    if (!o.quiet) {
        std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
        std::fprintf(stderr,
                     "tessera-creaturegen: wrote %s in %.1f s\n"
                     "  cage %u triangles, %zu vertices (%llu bytes uncompressed, %llu Draco)\n"
                     "  sculpt %u triangles; maps %ux%u, scale %.6f bias %.6f, %llu misses of %llu texels\n",
                     o.out.string().c_str(), elapsed.count(), cage.triangleCount(), cage.vertices.size(),
                     static_cast<unsigned long long>(plainBytes), static_cast<unsigned long long>(dracoBytes),
                     creature.sculpt.triangleCount(), disp.image.width, disp.image.height, disp.scale, disp.bias,
                     static_cast<unsigned long long>(baked.stats.misses),
                     static_cast<unsigned long long>(baked.stats.texelsCovered));
        std::fprintf(stderr,
                     "  Catmull-Clark tiles %s: %u ptex faces of %ux%u, %llu misses; error rms %.5f max %.5f m "
                     "(planar rms %.5f max %.5f)\n",
                     tilesFile.filename().string().c_str(), cc.ptexFaces, 1u << cc.tileLog2Size, 1u << cc.tileLog2Size,
                     static_cast<unsigned long long>(cc.misses), cc.subdiv.rms, cc.subdiv.max, cc.planar.rms,
                     cc.planar.max);
        if (creature.far) {
            std::fprintf(stderr, "  far mesh %u triangles (%s), error %.4f of the extent (%.4f m)\n",
                         creature.far->mesh.triangleCount(), character::farMeshMethodName(creature.far->method),
                         creature.far->relativeError, creature.far->absoluteError);
        }
    }
    return 0;
}
