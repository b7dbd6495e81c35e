// Error messages name the file and the problem; a hand-built .glb carries the
// displacement map extras (a 16-bit PNG) through the loader exactly.
#include "tessera/assets/GltfLoader.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <png.h>

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

void appendPng(png_structp png, png_bytep data, png_size_t size) {
    auto* out = static_cast<std::string*>(png_get_io_ptr(png));
    out->append(reinterpret_cast<const char*>(data), size);
}

// A 16-bit grayscale PNG, written with libpng.
std::string png16(uint32_t width, uint32_t height, const std::vector<uint16_t>& texels) {
    std::string out;
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    png_set_write_fn(png, &out, appendPng, nullptr);
    png_set_IHDR(png, info, width, height, 16, PNG_COLOR_TYPE_GRAY, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    std::vector<uint8_t> row(width * 2);
    for (uint32_t y = 0; y < height; ++y) {
        for (uint32_t x = 0; x < width; ++x) {
            uint16_t v = texels[y * width + x];
            row[x * 2] = static_cast<uint8_t>(v >> 8);  // PNG is big-endian
            row[x * 2 + 1] = static_cast<uint8_t>(v & 0xFF);
        }
        png_write_row(png, row.data());
    }
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    return out;
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
