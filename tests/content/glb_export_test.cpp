// The .glb exporter: container layout, determinism, the KHR_draco_mesh_compression
// declarations, and (because the Khronos validator cannot decode Draco) the
// decoded Draco geometry compared with an uncompressed export of the same asset.
#include "GlbTestCharacter.h"
#include "GlbTestReader.h"
#include "creature/CreatureGenerator.h"
#include "creature/GlbExporter.h"

#include "tessera/core/ImageFile.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <cmath>
#include <filesystem>
#include <fstream>

namespace {

namespace fs = std::filesystem;
using tessera::creature::ExportOptions;
using tessera::creature::exportGlb;
using tessera::test::GlbFile;
using tessera::test::GlbPrimitive;

fs::path outputDir() {
    fs::path dir = fs::path(TESSERA_TEST_OUTPUT_DIR) / "glb_export";
    fs::create_directories(dir);
    return dir;
}

std::vector<uint8_t> readBytes(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Exports the test character and returns the file's bytes.
std::vector<uint8_t> exportBytes(const fs::path& file, bool draco) {
    ExportOptions options;
    options.draco = draco;
    auto status = exportGlb(tessera::test::makeTestCharacter(), file, options);
    EXPECT_TRUE(status.ok()) << (status.ok() ? "" : status.error().message);
    return readBytes(file);
}

TEST(GlbExport, ContainerIsAlignedGlbVersion2) {
    for (bool draco : {false, true}) {
        std::vector<uint8_t> bytes = exportBytes(outputDir() / "layout.glb", draco);
        ASSERT_GE(bytes.size(), 28u);
        EXPECT_EQ(0, std::memcmp(bytes.data(), "glTF", 4));
        EXPECT_EQ(tessera::test::readU32(bytes, 4), 2u);
        EXPECT_EQ(tessera::test::readU32(bytes, 8), bytes.size());
        uint32_t jsonLength = tessera::test::readU32(bytes, 12);
        EXPECT_EQ(jsonLength % 4, 0u);
        EXPECT_EQ(bytes.size() % 4, 0u);
        GlbFile file = tessera::test::parseGlb(bytes);
        EXPECT_EQ(file.bin.size() % 4, 0u);
        EXPECT_EQ(file.json["buffers"][0]["byteLength"].get<size_t>(), file.bin.size());
        for (const auto& view : file.json["bufferViews"]) EXPECT_EQ(view.value("byteOffset", 0) % 4, 0);
        EXPECT_EQ(file.json["asset"]["generator"], "Tessera creaturegen");
        EXPECT_EQ(file.json["asset"]["version"], "2.0");
    }
}

TEST(GlbExport, SameAssetGivesSameBytes) {
    for (bool draco : {false, true}) {
        std::vector<uint8_t> first = exportBytes(outputDir() / "determinism_a.glb", draco);
        std::vector<uint8_t> second = exportBytes(outputDir() / "determinism_b.glb", draco);
        EXPECT_FALSE(first.empty());
        EXPECT_EQ(first, second) << (draco ? "Draco" : "plain");
    }
}

TEST(GlbExport, DracoPrimitiveFollowsTheExtension) {
    GlbFile file = tessera::test::parseGlb(exportBytes(outputDir() / "extension.glb", true));
    const auto& doc = file.json;
    EXPECT_EQ(doc["extensionsUsed"], nlohmann::json::array({"KHR_draco_mesh_compression"}));
    EXPECT_EQ(doc["extensionsRequired"], nlohmann::json::array({"KHR_draco_mesh_compression"}));
    const auto& primitive = doc["meshes"][0]["primitives"][0];
    const auto& extension = primitive["extensions"]["KHR_draco_mesh_compression"];
    ASSERT_TRUE(extension.contains("bufferView"));
    for (const char* name : {"POSITION", "NORMAL", "TANGENT", "TEXCOORD_0", "JOINTS_0", "WEIGHTS_0"}) {
        ASSERT_TRUE(extension["attributes"].contains(name)) << name;
        const auto& accessor = doc["accessors"][primitive["attributes"][name].get<size_t>()];
        EXPECT_FALSE(accessor.contains("bufferView")) << name;
        EXPECT_FALSE(accessor.contains("byteOffset")) << name;
        EXPECT_TRUE(accessor.contains("count") && accessor.contains("componentType") && accessor.contains("type"));
    }
    const auto& position = doc["accessors"][primitive["attributes"]["POSITION"].get<size_t>()];
    EXPECT_TRUE(position.contains("min") && position.contains("max"));
    EXPECT_FALSE(doc["accessors"][primitive["indices"].get<size_t>()].contains("bufferView"));

    GlbFile plain = tessera::test::parseGlb(exportBytes(outputDir() / "plain.glb", false));
    EXPECT_FALSE(plain.json.contains("extensionsUsed"));
    EXPECT_FALSE(plain.json.contains("extensionsRequired"));
    EXPECT_TRUE(plain.json["accessors"][0].contains("bufferView"));
}

std::array<uint32_t, 3> canonical(uint32_t a, uint32_t b, uint32_t c) {
    // Rotate (keeping the winding) so the smallest index comes first.
    if (b < a && b < c) return {b, c, a};
    if (c < a && c < b) return {c, a, b};
    return {a, b, c};
}

// Exports `asset` both ways and checks that the decoded Draco primitive is
// the uncompressed one within the quantisation bounds, vertex for vertex and
// triangle for triangle.
void expectDracoMatchesPlain(const tessera::character::CharacterAsset& asset, const std::string& name) {
    const ExportOptions bits;
    ExportOptions plainOptions;
    plainOptions.draco = false;
    fs::path plainFile = outputDir() / (name + "_plain.glb"), dracoFile = outputDir() / (name + "_draco.glb");
    ASSERT_TRUE(exportGlb(asset, plainFile, plainOptions).ok());
    ASSERT_TRUE(exportGlb(asset, dracoFile, bits).ok());
    GlbPrimitive plain = tessera::test::readPrimitive(tessera::test::parseGlb(readBytes(plainFile)));
    GlbPrimitive draco = tessera::test::readPrimitive(tessera::test::parseGlb(readBytes(dracoFile)));
    // Edgebreaker duplicates a vertex whose triangles form more than one fan
    // (index-space bowties where UV charts meet), so the decoded primitive
    // may hold a few more vertices, never fewer, and the same triangles.
    ASSERT_GE(draco.positions.size(), plain.positions.size());
    ASSERT_LE(draco.positions.size(), plain.positions.size() + plain.positions.size() / 100) << name;
    ASSERT_EQ(draco.indices.size(), plain.indices.size());

    // The plain export is the asset exactly; Draco's bounds are half a
    // quantisation step of each attribute's range.
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const glm::vec3& p : plain.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
    const float extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
    const float positionBound = extent / float(1 << bits.dracoPositionBits);
    const float uvBound = 1.0f / float(1 << bits.dracoTexCoordBits);
    const float genericBound = 2.0f / float(1 << bits.dracoGenericBits);  // range [-1, 1]
    const float normalBound = 4.0f / float(1 << bits.dracoNormalBits);    // radians

    // Draco reorders vertices: match each decoded vertex to its source
    // (joints exact, position and uv within their bounds).
    std::vector<uint32_t> source(draco.positions.size());
    std::vector<int> used(plain.positions.size(), 0);
    float worstPosition = 0.0f, worstNormal = 0.0f, worstUv = 0.0f;
    for (size_t d = 0; d < draco.positions.size(); ++d) {
        float best = 1e30f;
        for (size_t p = 0; p < plain.positions.size(); ++p) {
            if (plain.joints[p] != draco.joints[d]) continue;
            glm::vec3 dp = glm::abs(plain.positions[p] - draco.positions[d]);
            glm::vec2 duv = glm::abs(plain.uvs[p] - draco.uvs[d]);
            float score = std::max({dp.x / positionBound, dp.y / positionBound, dp.z / positionBound,
                                    duv.x / uvBound, duv.y / uvBound});
            if (score < best) best = score, source[d] = static_cast<uint32_t>(p);
        }
        ASSERT_LE(best, 1.0f) << name << ": decoded vertex " << d << " matches no source vertex within the bounds";
        uint32_t p = source[d];
        ++used[p];
        glm::vec3 dp = glm::abs(plain.positions[p] - draco.positions[d]);
        glm::vec2 duv = glm::abs(plain.uvs[p] - draco.uvs[d]);
        worstPosition = std::max({worstPosition, dp.x, dp.y, dp.z});
        worstUv = std::max({worstUv, duv.x, duv.y});
        float cosine = glm::dot(glm::normalize(plain.normals[p]), glm::normalize(draco.normals[d]));
        float angle = std::acos(std::clamp(cosine, -1.0f, 1.0f));
        worstNormal = std::max(worstNormal, angle);
        EXPECT_LE(angle, normalBound) << name << ": vertex " << d;
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(draco.tangents[d][c], plain.tangents[p][c], genericBound);
        EXPECT_EQ(draco.tangents[d].w, plain.tangents[p].w);
        for (int c = 0; c < 4; ++c) EXPECT_NEAR(draco.weights[d][c], plain.weights[p][c], genericBound / 2.0f);
    }
    EXPECT_TRUE(std::all_of(used.begin(), used.end(), [](int n) { return n >= 1; })) << name << ": a vertex was lost";

    std::vector<std::array<uint32_t, 3>> expected, decoded;
    for (size_t t = 0; t < plain.indices.size(); t += 3) {
        expected.push_back(canonical(plain.indices[t], plain.indices[t + 1], plain.indices[t + 2]));
        decoded.push_back(canonical(source[draco.indices[t]], source[draco.indices[t + 1]], source[draco.indices[t + 2]]));
    }
    std::sort(expected.begin(), expected.end());
    std::sort(decoded.begin(), decoded.end());
    EXPECT_EQ(decoded, expected) << name;
    std::printf("%s: %zu vertices, %zu triangles; %ju bytes Draco, %ju bytes plain; worst errors: position %.3g "
                "(bound %.3g), uv %.3g (bound %.3g), normal %.3g deg (bound %.3g)\n",
                name.c_str(), draco.positions.size(), draco.indices.size() / 3, uintmax_t(fs::file_size(dracoFile)),
                uintmax_t(fs::file_size(plainFile)), worstPosition, positionBound, worstUv, uvBound,
                worstNormal * 57.2957795f, normalBound * 57.2957795f);
}

TEST(GlbExport, DecodedDracoMatchesUncompressedExport) {
    expectDracoMatchesPlain(tessera::test::makeTestCharacter(), "synthetic");
}

// A real cage: a generated creature (small sculpt, no maps: only the cage
// matters here).
TEST(GlbExport, DecodedDracoMatchesUncompressedCreatureCage) {
    tessera::creature::CreatureOptions options;
    options.sculptTriangles = 20'000;
    tessera::creature::Creature creature = tessera::creature::generateCreature(options);
    expectDracoMatchesPlain(creature.asset, "creature_cage");
}

TEST(GlbExport, SkinAnimationsAndMapsAreExact) {
    const tessera::character::CharacterAsset asset = tessera::test::makeTestCharacter();
    GlbFile plain = tessera::test::parseGlb(exportBytes(outputDir() / "plain.glb", false));
    GlbFile draco = tessera::test::parseGlb(exportBytes(outputDir() / "draco.glb", true));
    EXPECT_EQ(plain.json["animations"], draco.json["animations"]);
    EXPECT_EQ(plain.json["materials"], draco.json["materials"]);

    for (const GlbFile* file : {&plain, &draco}) {
        const auto& doc = file->json;
        // Nodes keep the skeleton's indices; the mesh node comes last.
        ASSERT_EQ(doc["nodes"].size(), asset.skeleton.nodes.size() + 1);
        EXPECT_EQ(doc["nodes"][1]["name"], "spine");
        EXPECT_EQ(doc["skins"][0]["joints"], nlohmann::json::array({0, 1, 2}));
        std::vector<float> ibm = tessera::test::readAccessor(*file, doc["skins"][0]["inverseBindMatrices"].get<size_t>());
        ASSERT_EQ(ibm.size(), 48u);
        EXPECT_EQ(ibm[16 + 13], -1.0f);

        ASSERT_EQ(doc["animations"].size(), asset.clips.size());
        for (size_t c = 0; c < asset.clips.size(); ++c) {
            const auto& animation = doc["animations"][c];
            EXPECT_EQ(animation["name"], asset.clips[c].name);
            for (size_t k = 0; k < asset.clips[c].channels.size(); ++k) {
                const auto& channel = asset.clips[c].channels[k];
                const auto& sampler = animation["samplers"][animation["channels"][k]["sampler"].get<size_t>()];
                EXPECT_EQ(tessera::test::readAccessor(*file, sampler["input"].get<size_t>()), channel.times);
                std::vector<float> values = tessera::test::readAccessor(*file, sampler["output"].get<size_t>());
                size_t n = values.size() / channel.values.size();
                for (size_t i = 0; i < channel.values.size(); ++i) {
                    for (size_t j = 0; j < n; ++j) EXPECT_EQ(values[i * n + j], channel.values[i][int(j)]);
                }
            }
        }
        const auto& extras = doc["materials"][0]["extras"]["tessera_displacement"];
        EXPECT_EQ(extras["scale"].get<float>(), asset.displacement->scale);
        EXPECT_EQ(extras["bias"].get<float>(), asset.displacement->bias);

        // Decode the embedded PNGs: texels must come back exactly.
        const tessera::character::TextureImage* maps[] = {&*asset.baseColor, &*asset.normalMap, &asset.displacement->image};
        size_t textures[] = {doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["index"].get<size_t>(),
                             doc["materials"][0]["normalTexture"]["index"].get<size_t>(), extras["texture"].get<size_t>()};
        for (int m = 0; m < 3; ++m) {
            const auto& image = doc["images"][doc["textures"][textures[m]]["source"].get<size_t>()];
            EXPECT_EQ(image["mimeType"], "image/png");
            std::vector<uint8_t> png = tessera::test::bufferViewBytes(*file, image["bufferView"].get<size_t>());
            // The code base's one image decoder (the loader's).
            const bool r16 = maps[m]->format == tessera::character::TextureFormat::R16;
            auto decoded = tessera::decodeImage(png, r16 ? tessera::PngLayout::Gray16 : tessera::PngLayout::Rgba8);
            ASSERT_TRUE(decoded) << decoded.error().message;
            EXPECT_EQ(decoded->width, maps[m]->width);
            EXPECT_EQ(decoded->bytes, maps[m]->bytes) << "map " << m;  // 16-bit samples come back host (little) endian
        }
    }
}

TEST(GlbExport, ErrorsNameTheFile) {
    auto asset = tessera::test::makeTestCharacter();
    auto missingDir = exportGlb(asset, outputDir() / "no_such_dir" / "x.glb");
    ASSERT_FALSE(missingDir.ok());
    EXPECT_NE(missingDir.error().message.find("x.glb"), std::string::npos) << missingDir.error().message;

    asset.cage.indices.back() = 1000;
    auto badIndex = exportGlb(asset, outputDir() / "bad_index.glb");
    ASSERT_FALSE(badIndex.ok());
    EXPECT_EQ(badIndex.error().message.rfind("bad_index.glb: ", 0), 0u) << badIndex.error().message;

    asset = tessera::test::makeTestCharacter();
    asset.clips[0].channels[0].times = {0.0f, 0.5f, 0.5f};
    auto badTimes = exportGlb(asset, outputDir() / "bad_times.glb");
    ASSERT_FALSE(badTimes.ok());
    EXPECT_NE(badTimes.error().message.find("bad_times.glb: clip 'bend'"), std::string::npos) << badTimes.error().message;

    ExportOptions options;
    options.dracoPositionBits = 31;
    auto badBits = exportGlb(tessera::test::makeTestCharacter(), outputDir() / "bad_bits.glb", options);
    ASSERT_FALSE(badBits.ok());
    EXPECT_NE(badBits.error().message.find("bad_bits.glb"), std::string::npos);
}

} // namespace
