// The far LOD mesh on load: files without MSFT_lod (every Khronos sample)
// get one made by character::simplifyCage; a file's MSFT_lod level is read
// when it is sound, and a broken one fails with one line naming the file,
// the JSON pointer and the problem.
#include "tessera/assets/GltfLoader.h"
#include "tessera/character/FarMesh.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <tuple>

namespace fs = std::filesystem;
using tessera::assets::loadCharacter;
using tessera::character::CageMesh;
using tessera::character::CharacterAsset;

namespace {

const fs::path kSamples = fs::path(TESSERA_TESTDATA_DIR) / "gltf";

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
    return static_cast<size_t>(std::count_if(uses.begin(), uses.end(), [](const auto& e) { return e.second == 1; }));
}

void expectSamePalette(const CageMesh& far, const CageMesh& cage, const fs::path& file) {
    ASSERT_EQ(far.bindings.size(), cage.bindings.size()) << file;
    for (size_t b = 0; b < cage.bindings.size(); ++b) {
        EXPECT_EQ(far.bindings[b].node, cage.bindings[b].node) << file;
        EXPECT_EQ(far.bindings[b].inverseBind, cage.bindings[b].inverseBind) << file;
    }
}

// SimpleSkin (embedded buffers, so the copy needs no other file) with its
// JSON changed by `edit`, written to the test output folder.
fs::path editedSimpleSkin(const std::string& name, const std::function<void(nlohmann::json&)>& edit) {
    std::ifstream in(kSamples / "SimpleSkin" / "glTF-Embedded" / "SimpleSkin.gltf");
    nlohmann::json doc = nlohmann::json::parse(in);
    edit(doc);
    fs::path dir = fs::path(TESSERA_TEST_OUTPUT_DIR) / "far_lod";
    fs::create_directories(dir);
    fs::path file = dir / (name + ".gltf");
    std::ofstream(file) << doc.dump();
    return file;
}

// Node 0 is SimpleSkin's skinned mesh node; `ids` becomes its MSFT_lod.
void addLod(nlohmann::json& doc, const nlohmann::json& ids) {
    doc["nodes"][0]["extensions"]["MSFT_lod"] = {{"ids", ids}};
    doc["extensionsUsed"] = nlohmann::json::array({"MSFT_lod"});
}

} // namespace

TEST(GltfFarLod, CesiumManGetsOneMadeAtLoadTime) {
    for (const char* variant : {"glTF/CesiumMan.gltf", "glTF-Binary/CesiumMan.glb", "glTF-Draco/CesiumMan.gltf"}) {
        fs::path file = kSamples / "CesiumMan" / variant;
        auto loaded = loadCharacter(file);
        ASSERT_TRUE(loaded.ok()) << loaded.error().message;
        const CharacterAsset& asset = loaded.value();
        ASSERT_TRUE(asset.farMesh.has_value()) << file;
        const CageMesh& far = *asset.farMesh;
        auto again = tessera::character::simplifyCage(asset.cage);
        ASSERT_TRUE(again.ok());
        std::printf("%s: cage %u triangles -> far %u triangles, %zu vertices, %s, error %.4f (%.4f units), "
                    "%u seam triangles, %zu boundary edges (cage %zu)\n",
                    variant, asset.cage.triangleCount(), far.triangleCount(), far.vertices.size(),
                    tessera::character::farMeshMethodName(again->method), again->relativeError, again->absoluteError,
                    again->seamTriangles, boundaryEdges(far), boundaryEdges(asset.cage));
        EXPECT_EQ(far.indices, again->mesh.indices) << "made by simplifyCage with the default settings";
        EXPECT_LE(far.triangleCount(), 300u) << file;
        EXPECT_GE(far.triangleCount(), 200u) << file;
        expectSamePalette(far, asset.cage, file);
        for (const auto& v : far.vertices) {
            for (int c = 0; c < 4; ++c) ASSERT_LT(v.joints[c], far.bindings.size());
        }
    }
}

TEST(GltfFarLod, EverySampleHasAFarMeshWithTheCagesPalette) {
    size_t files = 0;
    for (const auto& model : fs::directory_iterator(kSamples)) {
        if (!model.is_directory()) continue;
        for (const auto& variant : fs::directory_iterator(model.path())) {
            if (!variant.is_directory()) continue;
            for (const auto& file : fs::directory_iterator(variant.path())) {
                std::string ext = file.path().extension().string();
                if (ext != ".gltf" && ext != ".glb") continue;
                auto loaded = loadCharacter(file.path());
                ASSERT_TRUE(loaded.ok()) << loaded.error().message;
                ASSERT_TRUE(loaded->farMesh.has_value()) << file.path();
                EXPECT_GT(loaded->farMesh->triangleCount(), 0u) << file.path();
                EXPECT_LE(loaded->farMesh->triangleCount(), 300u) << file.path();
                expectSamePalette(*loaded->farMesh, loaded->cage, file.path());
                ++files;
            }
        }
    }
    EXPECT_GE(files, 30u);
}

TEST(GltfFarLod, ReadsASoundLevel) {
    // Node 3: the same mesh and skin as node 0, outside the scene.
    fs::path file = editedSimpleSkin("sound", [](nlohmann::json& doc) {
        doc["nodes"].push_back({{"mesh", 0}, {"skin", 0}});
        addLod(doc, {3});
    });
    auto loaded = loadCharacter(file);
    ASSERT_TRUE(loaded.ok()) << loaded.error().message;
    ASSERT_TRUE(loaded->farMesh.has_value());
    // The level is the cage's own mesh here, so it reads back identical.
    EXPECT_EQ(loaded->farMesh->indices, loaded->cage.indices);
    ASSERT_EQ(loaded->farMesh->vertices.size(), loaded->cage.vertices.size());
    for (size_t v = 0; v < loaded->cage.vertices.size(); ++v) {
        EXPECT_EQ(loaded->farMesh->vertices[v].position, loaded->cage.vertices[v].position);
        EXPECT_EQ(loaded->farMesh->vertices[v].joints, loaded->cage.vertices[v].joints);
    }
    expectSamePalette(*loaded->farMesh, loaded->cage, file);
    EXPECT_EQ(loaded->skeleton.nodes.size(), 3u) << "the level's node is not part of the skeleton";
}

TEST(GltfFarLod, BrokenLevelsFailWithOneLine) {
    struct Case {
        const char* name;
        std::function<void(nlohmann::json&)> edit;
        const char* expected;
    };
    const Case cases[] = {
        {"id_out_of_range", [](nlohmann::json& doc) { addLod(doc, {99}); },
         "/nodes/0/extensions/MSFT_lod/ids/0: unresolved reference 99"},
        {"id_not_an_index", [](nlohmann::json& doc) { addLod(doc, {"far"}); },
         "/nodes/0/extensions/MSFT_lod/ids/0: type mismatch"},
        {"no_ids", [](nlohmann::json& doc) { addLod(doc, nlohmann::json::array()); },
         "/nodes/0/extensions/MSFT_lod/ids"},
        {"itself", [](nlohmann::json& doc) { addLod(doc, {0}); },
         "/nodes/0/extensions/MSFT_lod/ids/0: a level of detail cannot refer to its own object"},
        {"in_scene", [](nlohmann::json& doc) { addLod(doc, {2}); },
         "/nodes/0/extensions/MSFT_lod/ids/0: MSFT_lod level node 2 is part of the scene"},
        {"no_mesh",
         [](nlohmann::json& doc) {
             doc["nodes"].push_back({{"name", "empty"}});
             addLod(doc, {3});
         },
         "/nodes/0/extensions/MSFT_lod/ids/0: MSFT_lod level node 3 has no mesh"},
        {"other_skin",
         [](nlohmann::json& doc) {
             doc["skins"].push_back(doc["skins"][0]);  // the same joints, but another skin
             doc["nodes"].push_back({{"mesh", 0}, {"skin", 1}});
             addLod(doc, {3});
         },
         "/nodes/0/extensions/MSFT_lod/ids/0: MSFT_lod level node 3 has skin 1, not the skin 0 of node 0"},
        {"not_declared",
         [](nlohmann::json& doc) {
             doc["nodes"].push_back({{"mesh", 0}, {"skin", 0}});
             doc["nodes"][0]["extensions"]["MSFT_lod"] = {{"ids", {3}}};
         },
         "/nodes/0/extensions/MSFT_lod: extension is not declared in extensionsUsed"},
    };
    for (const Case& c : cases) {
        fs::path file = editedSimpleSkin(c.name, c.edit);
        auto loaded = loadCharacter(file);
        ASSERT_FALSE(loaded.ok()) << c.name;
        const std::string& message = loaded.error().message;
        std::printf("%s\n", message.c_str());
        EXPECT_EQ(message.rfind(file.string() + ": ", 0), 0u) << message;
        EXPECT_NE(message.find(c.expected), std::string::npos) << c.name << ": " << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
}
