// The far LOD mesh of the generated creatures: made by generateCreature with
// character::simplifyCage, written by exportGlb as an MSFT_lod level, and
// read back by the engine's loader exactly as written.
#include "GlbTestReader.h"
#include "creature/CreatureGenerator.h"
#include "creature/GlbExporter.h"
#include "tessera/assets/GltfLoader.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <tuple>

namespace fs = std::filesystem;
using tessera::character::CageMesh;

namespace {

std::vector<uint8_t> readBytes(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

const tessera::creature::Creature& smallCreature() {
    static const tessera::creature::Creature creature = [] {
        tessera::creature::CreatureOptions options;  // the build's 5K cage; a small sculpt is enough here
        options.seed = 1;
        options.sculptTriangles = 20'000;
        options.baseColorSize = 64;
        return tessera::creature::generateCreature(options);
    }();
    return creature;
}

// Edges used by one triangle only, with vertices welded by position.
size_t boundaryEdges(const CageMesh& mesh) {
    std::map<std::tuple<float, float, float>, uint32_t> weld;
    auto id = [&](uint32_t v) {
        const glm::vec3& p = mesh.vertices[v].position;
        return weld.emplace(std::make_tuple(p.x, p.y, p.z), uint32_t(weld.size())).first->second;
    };
    std::map<std::pair<uint32_t, uint32_t>, int> uses;
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
        for (size_t k = 0; k < 3; ++k) {
            uint32_t a = id(mesh.indices[t + k]), b = id(mesh.indices[t + (k + 1) % 3]);
            ++uses[{std::min(a, b), std::max(a, b)}];
        }
    size_t open = 0;
    for (const auto& [edge, count] : uses) open += count != 2;
    return open;
}

void expectSamePalette(const CageMesh& far, const CageMesh& cage) {
    ASSERT_EQ(far.bindings.size(), cage.bindings.size());
    for (size_t b = 0; b < cage.bindings.size(); ++b) {
        EXPECT_EQ(far.bindings[b].node, cage.bindings[b].node);
        EXPECT_EQ(far.bindings[b].inverseBind, cage.bindings[b].inverseBind);
    }
}

} // namespace

TEST(CreatureFarMesh, GeneratorMakesAClosedFewHundredTriangleMesh) {
    const auto& creature = smallCreature();
    ASSERT_TRUE(creature.asset.farMesh.has_value());
    ASSERT_TRUE(creature.far.has_value());
    const CageMesh& far = *creature.asset.farMesh;
    std::printf("froblin_1 (generator): cage %u -> far %u triangles, %zu vertices, %s, error %.4f (%.4f m), "
                "%u seam triangles\n",
                creature.asset.cage.triangleCount(), far.triangleCount(), far.vertices.size(),
                tessera::character::farMeshMethodName(creature.far->method), creature.far->relativeError,
                creature.far->absoluteError, creature.far->seamTriangles);
    EXPECT_GE(far.triangleCount(), 200u);
    EXPECT_LE(far.triangleCount(), 300u);
    EXPECT_EQ(boundaryEdges(far), 0u);
    EXPECT_LE(creature.far->relativeError, 0.05f);
    expectSamePalette(far, creature.asset.cage);
}

TEST(CreatureFarMesh, ExportedAsAnMsftLodLevelAndLoadedAsWritten) {
    const auto& creature = smallCreature();
    const CageMesh& written = *creature.asset.farMesh;
    fs::path dir = fs::path(TESSERA_TEST_OUTPUT_DIR) / "far_mesh";
    fs::create_directories(dir);
    for (bool draco : {true, false}) {
        tessera::creature::ExportOptions options;
        options.draco = draco;
        fs::path file = dir / (draco ? "froblin_draco.glb" : "froblin_plain.glb");
        ASSERT_TRUE(tessera::creature::exportGlb(creature.asset, file, options).ok());

        // The JSON: an optional extension, the level outside the scene, the same skin.
        nlohmann::json doc = tessera::test::parseGlb(readBytes(file)).json;
        EXPECT_NE(std::find(doc["extensionsUsed"].begin(), doc["extensionsUsed"].end(), "MSFT_lod"),
                  doc["extensionsUsed"].end());
        if (doc.contains("extensionsRequired")) {
            EXPECT_EQ(std::find(doc["extensionsRequired"].begin(), doc["extensionsRequired"].end(), "MSFT_lod"),
                      doc["extensionsRequired"].end());
        }
        const size_t meshNode = creature.asset.skeleton.nodes.size();
        const nlohmann::json& ids = doc["nodes"][meshNode]["extensions"]["MSFT_lod"]["ids"];
        ASSERT_EQ(ids.size(), 1u);
        const size_t farNode = ids[0].get<size_t>();
        EXPECT_EQ(doc["nodes"][farNode]["skin"], doc["nodes"][meshNode]["skin"]);
        EXPECT_EQ(doc["nodes"][farNode]["mesh"], 1);
        EXPECT_EQ(std::count(doc["scenes"][0]["nodes"].begin(), doc["scenes"][0]["nodes"].end(), farNode), 0);
        EXPECT_EQ(doc["nodes"][meshNode]["extras"]["MSFT_screencoverage"].size(), 2u);

        auto loaded = tessera::assets::loadCharacter(file);
        ASSERT_TRUE(loaded.ok()) << loaded.error().message;
        ASSERT_TRUE(loaded->farMesh.has_value());
        const CageMesh& read = *loaded->farMesh;
        EXPECT_EQ(read.indices, written.indices);
        ASSERT_EQ(read.vertices.size(), written.vertices.size());
        for (size_t v = 0; v < written.vertices.size(); ++v) {
            const auto &a = read.vertices[v], &b = written.vertices[v];
            // Floats are stored as written; the loader renormalises normals
            // and weights, which may move their last bit.
            EXPECT_EQ(a.position, b.position) << v;
            EXPECT_EQ(a.uv, b.uv) << v;
            EXPECT_EQ(a.tangent, b.tangent) << v;
            EXPECT_LT(glm::length(a.normal - b.normal), 1e-6f) << v;
            EXPECT_LT(glm::length(a.weights - b.weights), 1e-6f) << v;
            for (int c = 0; c < 4; ++c) {
                if (b.weights[c] > 0.0f) {
                    EXPECT_EQ(a.joints[c], b.joints[c]) << v;
                }
            }
        }
        expectSamePalette(read, loaded->cage);
    }
}

TEST(CreatureFarMesh, ExportIsDeterministic) {
    const auto& creature = smallCreature();
    fs::path dir = fs::path(TESSERA_TEST_OUTPUT_DIR) / "far_mesh";
    fs::create_directories(dir);
    ASSERT_TRUE(tessera::creature::exportGlb(creature.asset, dir / "a.glb").ok());
    ASSERT_TRUE(tessera::creature::exportGlb(creature.asset, dir / "b.glb").ok());
    EXPECT_EQ(readBytes(dir / "a.glb"), readBytes(dir / "b.glb"));
}

// The creatures the build ships (tessera-creaturegen, seeds 1 to 3).
TEST(CreatureFarMesh, ShippedCreaturesCarryTheirFarMesh) {
    for (int seed = 1; seed <= 3; ++seed) {
        fs::path file = fs::path(TESSERA_BINARY_DIR) / "content" / "characters" / ("froblin_" + std::to_string(seed) + ".glb");
        if (!fs::exists(file)) GTEST_SKIP() << file << " not built";
        nlohmann::json doc = tessera::test::parseGlb(readBytes(file)).json;
        ASSERT_TRUE(doc["meshes"].size() == 2u) << file << ": no far LOD mesh (rebuild tessera_characters)";
        auto loaded = tessera::assets::loadCharacter(file);
        ASSERT_TRUE(loaded.ok()) << loaded.error().message;
        ASSERT_TRUE(loaded->farMesh.has_value());
        const CageMesh& far = *loaded->farMesh;
        std::ifstream reportFile(fs::path(file).replace_extension(".json"));
        nlohmann::json report = nlohmann::json::parse(reportFile, nullptr, false);
        std::printf("froblin_%d.glb: far %u triangles, %zu vertices, %zu open edges; report: %s, error %s (%s m), "
                    "%s seam triangles\n",
                    seed, far.triangleCount(), far.vertices.size(), boundaryEdges(far),
                    report.value("far_method", std::string("?")).c_str(), report.value("far_error_relative", nlohmann::json()).dump().c_str(),
                    report.value("far_error", nlohmann::json()).dump().c_str(),
                    report.value("far_seam_triangles", nlohmann::json()).dump().c_str());
        EXPECT_GE(far.triangleCount(), 200u);
        EXPECT_LE(far.triangleCount(), 300u);
        EXPECT_EQ(boundaryEdges(far), 0u);
        EXPECT_EQ(report.value("far_triangles", 0u), far.triangleCount());
        expectSamePalette(far, loaded->cage);
    }
}
