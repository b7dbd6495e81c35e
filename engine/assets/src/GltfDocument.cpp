#include "GltfDocument.h"

#include "DracoDecoder.h"
#include "GlbContainer.h"
#include "GltfDataValidator.h"
#include "GltfGraphValidator.h"
#include "GltfMeshValidator.h"
#include "GltfResourceValidator.h"
#include "GltfSchemaValidator.h"

#include <fstream>
#include <tuple>

namespace tessera::assets {

namespace fs = std::filesystem;

namespace {

// Files above this are refused before any allocation (a character is a few MiB).
constexpr uintmax_t kMaxFileBytes = uintmax_t{1} << 31;

std::vector<uint8_t> readFile(const fs::path& file) {
    std::error_code ec;
    if (!fs::is_regular_file(file, ec)) raise("", "file not found or not a regular file");
    uintmax_t size = fs::file_size(file, ec);
    if (ec) raise("", "cannot read the file size");
    if (size > kMaxFileBytes) raise("", "file is too large (" + std::to_string(size) + " bytes)");
    std::vector<uint8_t> bytes(static_cast<size_t>(size));
    std::ifstream in(file, std::ios::binary);
    if (!in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(size)))
        raise("", "cannot read the file");
    return bytes;
}

// Keeps the encoded bytes: TextureDecoder decodes only the images it needs.
bool keepEncodedImage(tinygltf::Image* image, int, std::string*, std::string*, int, int, const unsigned char* bytes,
                      int size, void*) {
    image->image.assign(bytes, bytes + size);
    image->as_is = true;
    return true;
}

} // namespace

GltfDocument GltfDocument::load(const fs::path& file) {
    std::vector<uint8_t> bytes = readFile(file);
    bool glb = hasGlbMagic(bytes) || file.extension() == ".glb";
    GlbChunks chunks;
    if (glb) chunks = parseGlb(bytes);
    else chunks.json = std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    if (chunks.json.size() >= 3 && static_cast<uint8_t>(chunks.json[0]) == 0xEF)
        raise("", "invalid JSON (byte order mark)");

    GltfDocument doc;
    doc.mJson = nlohmann::json::parse(chunks.json.begin(), chunks.json.end(), nullptr, false);
    if (doc.mJson.is_discarded()) raise("", chunks.json.empty() ? "not a glTF file (empty)" : "not a glTF file (invalid JSON)");
    if (!doc.mJson.is_object()) raise("", "not a glTF file (the JSON is not an object)");

    JsonChecker json(doc.mJson);
    GltfSchemaValidator(json).validate();
    GltfResourceValidator(json, file.parent_path(), glb, chunks.bin).validate();
    GltfLayoutValidator layout(json);
    layout.validate();
    GltfMeshValidator(json, layout).validate();
    GltfGraphValidator(json, layout).validate();

    // tinygltf refuses an indices accessor without a buffer view, which Draco primitives (and
    // all-zero accessors) legitimately have: it gets the JSON without those `indices`, and they
    // are put back on the model afterwards.
    nlohmann::json forTinyGltf = doc.mJson;
    std::vector<std::tuple<size_t, size_t, int>> heldIndices;
    for (size_t m = 0; m < json.count("meshes"); ++m)
        for (size_t p = 0; p < forTinyGltf["meshes"][m]["primitives"].size(); ++p) {
            nlohmann::json& primitive = forTinyGltf["meshes"][m]["primitives"][p];
            if (!primitive.contains("indices")) continue;
            int indices = primitive["indices"].get<int>();
            if (doc.mJson["accessors"][static_cast<size_t>(indices)].contains("bufferView")) continue;
            heldIndices.emplace_back(m, p, indices);
            primitive.erase("indices");
        }
    std::string text = heldIndices.empty() ? std::string(chunks.json) : forTinyGltf.dump();
    std::vector<uint8_t> glbBytes = glb && !heldIndices.empty() ? makeGlb(text, chunks.bin) : std::vector<uint8_t>();
    const std::vector<uint8_t>& binary = glbBytes.empty() ? bytes : glbBytes;

    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(keepEncodedImage, nullptr);
    std::string err, warn;
    std::string folder = file.parent_path().empty() ? std::string(".") : file.parent_path().string();
    bool ok = glb ? loader.LoadBinaryFromMemory(&doc.mModel, &err, &warn, binary.data(),
                                                static_cast<unsigned int>(binary.size()), folder)
                  : loader.LoadASCIIFromString(&doc.mModel, &err, &warn, text.data(),
                                               static_cast<unsigned int>(text.size()), folder);
    if (!ok) {
        std::string line = err.substr(0, err.find('\n'));
        raise("", "tinygltf: " + (line.empty() ? std::string("parse failed") : line));
    }
    if (doc.mModel.meshes.size() != json.count("meshes")) raise("", "tinygltf: mesh count differs from the JSON");
    for (auto [m, p, indices] : heldIndices) doc.mModel.meshes[m].primitives[p].indices = indices;
    decodeDracoPrimitives(doc.mModel);
    GltfDataValidator(doc.mModel, doc.mJson).validate();
    return doc;
}

} // namespace tessera::assets
