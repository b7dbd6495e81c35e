// Error messages name the file and the problem; a hand-built .glb carries the
// displacement map extras (a 16-bit PNG) through the loader exactly.
#include "tessera/assets/GltfLoader.h"
#include "tessera/core/ImageFile.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstring>
#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;
using tessera::assets::loadCharacter;

namespace {

fs::path outputDir() {
    fs::path dir = fs::path(TESSERA_TEST_OUTPUT_DIR).empty() ? fs::temp_directory_path() : fs::path(TESSERA_TEST_OUTPUT_DIR);
    dir /= "gltf_loader";
    fs::create_directories(dir);
    return dir;
}

void writeBytes(const fs::path& file, const std::string& bytes) {
    std::ofstream out(file, std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

std::string errorOf(const fs::path& file) {
    auto result = loadCharacter(file);
    EXPECT_FALSE(result.ok()) << file;
    return result ? std::string() : result.error().message;
}

// A 16-bit grayscale PNG, from the core's encoder.
std::string png16(uint32_t width, uint32_t height, const std::vector<uint16_t>& texels) {
    auto png = tessera::encodePng({width, height, tessera::PngLayout::Gray16, texels.data()});
    EXPECT_TRUE(png.ok());
    return png ? std::string(png->begin(), png->end()) : std::string();
}

std::string glb(const nlohmann::json& json, std::string bin) {
    std::string text = json.dump();
    while (text.size() % 4) text += ' ';
    while (bin.size() % 4) bin += '\0';
    auto u32 = [](uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
    return "glTF" + u32(2) + u32(static_cast<uint32_t>(12 + 8 + text.size() + 8 + bin.size())) +
           u32(static_cast<uint32_t>(text.size())) + "JSON" + text + u32(static_cast<uint32_t>(bin.size())) +
           std::string("BIN\0", 4) + bin;
}

// One triangle, and optionally an image in the same buffer.
nlohmann::json triangleJson(size_t bufferLength, uint32_t accessorCount = 3) {
    return {
        {"asset", {{"version", "2.0"}}},
        {"scene", 0},
        {"scenes", {{{"nodes", {0}}}}},
        {"nodes", {{{"mesh", 0}}}},
        {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}}}}}}},
        {"accessors", {{{"bufferView", 0}, {"componentType", 5126}, {"count", accessorCount}, {"type", "VEC3"},
                        {"min", {0, 0, 0}}, {"max", {1, 1, 0}}}}},
        {"bufferViews", {{{"buffer", 0}, {"byteLength", 36}}}},
        {"buffers", {{{"byteLength", bufferLength}}}},
    };
}

std::string trianglePositions() {
    const float p[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    return std::string(reinterpret_cast<const char*>(p), sizeof p);
}

} // namespace

TEST(GltfErrors, MissingFile) {
    const fs::path file = outputDir() / "no_such_model.glb";
    std::string message = errorOf(file);
    // The message starts with the path as given, so the user knows which file.
    EXPECT_EQ(message.rfind(file.string() + ": ", 0), 0u) << message;
    EXPECT_NE(message.find("not found"), std::string::npos) << message;
}

TEST(GltfErrors, NotGltf) {
    fs::path file = outputDir() / "notes.gltf";
    writeBytes(file, "these are not the droids");
    std::string message = errorOf(file);
    EXPECT_EQ(message.rfind(file.string() + ": ", 0), 0u) << message;
    EXPECT_NE(message.find("not a glTF file"), std::string::npos) << message;
}

TEST(GltfErrors, TruncatedGlb) {
    std::ifstream in(fs::path(TESSERA_TESTDATA_DIR) / "gltf/CesiumMan/glTF-Binary/CesiumMan.glb", std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ASSERT_GT(bytes.size(), 4096u);
    fs::path file = outputDir() / "truncated.glb";
    writeBytes(file, bytes.substr(0, 4096));
    std::string message = errorOf(file);
    EXPECT_EQ(message.rfind(file.string() + ": GLB: ", 0), 0u) << message;
}

TEST(GltfErrors, AccessorOutOfRange) {
    fs::path file = outputDir() / "long_accessor.glb";
    writeBytes(file, glb(triangleJson(36, 4), trianglePositions()));
    std::string message = errorOf(file);
    EXPECT_EQ(message.rfind(file.string() + ": /accessors/0: byte range", 0), 0u) << message;
    EXPECT_NE(message.find("exceeds buffer view 0"), std::string::npos) << message;
}

TEST(GltfDisplacement, ExtrasCarryScaleBiasAndTexels) {
    const std::vector<uint16_t> texels = {0, 1000, 65535, 32768, 7, 40000};
    std::string image = png16(3, 2, texels);
    std::string bin = trianglePositions() + image;
    nlohmann::json json = triangleJson(bin.size());
    json["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 36}, {"byteLength", image.size()}});
    json["images"] = {{{"bufferView", 1}, {"mimeType", "image/png"}}};
    json["textures"] = {{{"source", 0}}};
    const float scale = 0.0123f, bias = -0.0051f;
    json["materials"] = {{{"extras", {{"tessera_displacement", {{"texture", 0}, {"scale", scale}, {"bias", bias}}}}}}};
    json["meshes"][0]["primitives"][0]["material"] = 0;
    fs::path file = outputDir() / "displaced.glb";
    writeBytes(file, glb(json, bin));

    auto result = loadCharacter(file);
    ASSERT_TRUE(result.ok()) << result.error().message;
    ASSERT_TRUE(result->displacement.has_value());
    const auto& d = *result->displacement;
    EXPECT_EQ(d.scale, scale);
    EXPECT_EQ(d.bias, bias);
    ASSERT_EQ(d.image.format, tessera::character::TextureFormat::R16);
    ASSERT_EQ(d.image.width, 3u);
    ASSERT_EQ(d.image.height, 2u);
    ASSERT_EQ(d.image.bytes.size(), texels.size() * 2);
    for (size_t i = 0; i < texels.size(); ++i) {
        uint16_t v;
        std::memcpy(&v, &d.image.bytes[i * 2], 2);
        EXPECT_EQ(v, texels[i]) << i;
    }
    EXPECT_EQ(result->cage.triangleCount(), 1u);
    EXPECT_EQ(result->cage.bindings.size(), 1u);
    EXPECT_NEAR(result->cage.vertices[0].normal.z, 1.0f, 1e-6f);  // generated
}
