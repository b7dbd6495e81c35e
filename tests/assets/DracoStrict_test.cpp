// KHR_draco_mesh_compression, strictly: a damaged Draco payload can decode
// "successfully" into other counts than the glTF accessors declare, or into
// values outside their min and max. Such a primitive is rejected with a
// message naming the file, the primitive and the mismatch, never drawn as
// corrupted geometry. The files here are derived from Khronos' Draco Duck:
// edited accessors, a truncated, zeroed or bit-flipped payload, wrong
// attribute ids.
#include "tessera/assets/GltfLoader.h"
#include "tessera/core/Random.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using tessera::character::CharacterAsset;

namespace {

const fs::path kDuck = fs::path(TESSERA_TESTDATA_DIR) / "gltf" / "Duck" / "glTF-Draco";
const fs::path kOut = fs::path(TESSERA_TEST_OUTPUT_DIR) / "draco_strict";
constexpr const char* kPrimitive = "/meshes/0/primitives/0";

std::vector<char> readBytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

nlohmann::json duckJson() { return nlohmann::json::parse(readBytes(kDuck / "Duck.gltf")); }

/// Writes a copy of the Draco Duck as `name`/Duck.gltf with `json` and
/// `payload` (its Duck.bin) and the texture beside it; returns the .gltf.
fs::path writeVariant(const std::string& name, const nlohmann::json& json, const std::vector<char>& payload) {
    const fs::path dir = kOut / name;
    fs::create_directories(dir);
    std::ofstream(dir / "Duck.gltf") << json.dump(1);
    std::ofstream(dir / "Duck.bin", std::ios::binary).write(payload.data(), std::streamsize(payload.size()));
    fs::copy_file(kDuck / "DuckCM.png", dir / "DuckCM.png", fs::copy_options::overwrite_existing);
    return dir / "Duck.gltf";
}

/// Loading `file` fails with one message naming the file, the primitive and `problem`.
void expectRejected(const fs::path& file, const std::string& problem) {
    auto loaded = tessera::assets::loadCharacter(file);
    ASSERT_FALSE(loaded.ok()) << file << " loaded";
    const std::string& message = loaded.error().message;
    std::cout << "[draco] " << message << "\n";
    EXPECT_NE(message.find(file.string()), std::string::npos) << message;
    EXPECT_NE(message.find(kPrimitive), std::string::npos) << message;
    EXPECT_NE(message.find(problem), std::string::npos) << message;
}

/// What a successful load must hold however the payload was damaged: the
/// declared counts, indices in range, finite positions within the declared
/// bounds (model space, before the node transform: compared in size only).
void expectConsistent(const CharacterAsset& asset, const CharacterAsset& original, const std::string& what) {
    ASSERT_EQ(asset.cage.vertices.size(), original.cage.vertices.size()) << what;
    ASSERT_EQ(asset.cage.indices.size(), original.cage.indices.size()) << what;
    for (uint32_t index : asset.cage.indices) ASSERT_LT(index, asset.cage.vertices.size()) << what;
    glm::vec3 lo(INFINITY), hi(-INFINITY), olo(INFINITY), ohi(-INFINITY);
    for (const auto& v : asset.cage.vertices) {
        ASSERT_TRUE(std::isfinite(v.position.x) && std::isfinite(v.position.y) && std::isfinite(v.position.z)) << what;
        lo = glm::min(lo, v.position);
        hi = glm::max(hi, v.position);
    }
    for (const auto& v : original.cage.vertices) {
        olo = glm::min(olo, v.position);
        ohi = glm::max(ohi, v.position);
    }
    const glm::vec3 slack = (ohi - olo) * (1.0f / 128.0f) + 1e-4f;
    EXPECT_TRUE(glm::all(glm::greaterThanEqual(lo, olo - slack)) && glm::all(glm::lessThanEqual(hi, ohi + slack)))
        << what << ": the mesh grew outside the declared bounds";
}

} // namespace

TEST(DracoStrict, TheDuckLoadsAsItIs) {
    auto loaded = tessera::assets::loadCharacter(writeVariant("untouched", duckJson(), readBytes(kDuck / "Duck.bin")));
    ASSERT_TRUE(loaded.ok()) << loaded.error().message;
    EXPECT_EQ(loaded->cage.vertices.size(), 2399u);
    EXPECT_EQ(loaded->cage.indices.size(), 12636u);
}

TEST(DracoStrict, AccessorCountsMustMatchTheDecodedMesh) {
    const auto payload = readBytes(kDuck / "Duck.bin");
    // One point fewer declared for every attribute (they must agree with
    // each other, which the schema checks first).
    nlohmann::json points = duckJson();
    for (int a : {1, 2, 3}) points["accessors"][a]["count"] = 2398;
    expectRejected(writeVariant("point_count", points, payload),
                   "KHR_draco_mesh_compression: decoded 2399 points for attribute NORMAL, but accessor 1 declares 2398");
    nlohmann::json indices = duckJson();
    indices["accessors"][0]["count"] = 12639;
    expectRejected(writeVariant("index_count", indices, payload),
                   "KHR_draco_mesh_compression: decoded 12636 indices, but accessor 0 declares 12639");
}

TEST(DracoStrict, DecodedValuesMustLieWithinMinAndMax) {
    nlohmann::json json = duckJson();
    json["accessors"][2]["max"] = {50.0, 80.0, 30.0}; // the Duck reaches 96, 164, 54
    expectRejected(writeVariant("position_max", json, readBytes(kDuck / "Duck.bin")),
                   "attribute POSITION decoded value");
}

TEST(DracoStrict, AttributeIdsMustExistInThePayload) {
    nlohmann::json json = duckJson();
    json["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"]["attributes"]["TEXCOORD_0"] = 7;
    expectRejected(writeVariant("attribute_id", json, readBytes(kDuck / "Duck.bin")),
                   "Draco attribute TEXCOORD_0 is not in the compressed mesh");
    // Two glTF attributes read from one Draco attribute: NORMAL's three
    // components are not TEXCOORD_0's two.
    json["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"]["attributes"]["TEXCOORD_0"] = 0;
    expectRejected(writeVariant("attribute_shared", json, readBytes(kDuck / "Duck.bin")),
                   "Draco attribute TEXCOORD_0 has 3 components, but accessor 3 has 2");
}

TEST(DracoStrict, ZeroedAndTruncatedPayloadsAreRejected) {
    const auto payload = readBytes(kDuck / "Duck.bin");
    expectRejected(writeVariant("zeroed", duckJson(), std::vector<char>(payload.size(), 0)), "Draco");
    // The view's length halved: the decoder sees half the stream.
    nlohmann::json half = duckJson();
    half["bufferViews"][0]["byteLength"] = 10366 / 2;
    expectRejected(writeVariant("half_view", half, payload), "Draco");
    // Every shorter cut of the stream itself, by the view's length.
    for (int cut : {1, 16, 100, 1000, 5000, 10000, 10365}) {
        nlohmann::json json = duckJson();
        json["bufferViews"][0]["byteLength"] = cut;
        expectRejected(writeVariant("cut_" + std::to_string(cut), json, payload), "Draco");
    }
}

// Bits flipped at seeded positions of the payload: each damaged file is
// either rejected, naming the file and the primitive, or loads into exactly
// the declared mesh within its bounds. Never a crash, never other counts.
TEST(DracoStrict, BitFlipsAreRejectedOrDecodeToTheDeclaredMesh) {
    const auto payload = readBytes(kDuck / "Duck.bin");
    auto original = tessera::assets::loadCharacter(kDuck / "Duck.gltf");
    ASSERT_TRUE(original.ok()) << original.error().message;
    tessera::Random random(17);
    int rejected = 0, accepted = 0;
    for (int trial = 0; trial < 160; ++trial) {
        auto damaged = payload;
        const int flips = 1 + trial % 4;
        std::string what = "flips";
        for (int f = 0; f < flips; ++f) {
            const size_t at = random.below(10366);
            const int b = int(random.below(8));
            damaged[at] = char(damaged[at] ^ (1 << b));
            what += " " + std::to_string(at) + ":" + std::to_string(b);
        }
        const fs::path file = writeVariant("flip", duckJson(), damaged);
        auto loaded = tessera::assets::loadCharacter(file);
        if (!loaded.ok()) {
            ++rejected;
            EXPECT_NE(loaded.error().message.find(file.string()), std::string::npos) << loaded.error().message;
            continue;
        }
        ++accepted;
        expectConsistent(loaded.value(), original.value(), what);
    }
    std::cout << "[draco] 160 damaged payloads: " << rejected << " rejected, " << accepted
              << " decoded to the declared mesh\n";
    EXPECT_GT(rejected, 0);
}
