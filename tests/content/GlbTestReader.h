#pragma once
/// @file GlbTestReader.h
/// A minimal .glb reader for the exporter tests, independent of the engine's
/// loader: container parsing, plain accessors, and the cage primitive
/// decoded from plain buffers or from KHR_draco_mesh_compression. Throws
/// std::runtime_error on anything it does not expect (a test failure).

#include <draco/compression/decode.h>
#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include <cstring>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace tessera::test {

/// The two chunks of a .glb file.
struct GlbFile {
    nlohmann::json json;
    std::vector<uint8_t> bin;
};

/// A triangle primitive as arrays, whatever its encoding.
struct GlbPrimitive {
    std::vector<glm::vec3> positions, normals;
    std::vector<glm::vec4> tangents, weights;
    std::vector<glm::vec2> uvs;
    std::vector<glm::u16vec4> joints;
    std::vector<uint32_t> indices;
};

inline uint32_t readU32(const std::vector<uint8_t>& bytes, size_t at) {
    if (at + 4 > bytes.size()) throw std::runtime_error("glb truncated");
    return uint32_t(bytes[at]) | uint32_t(bytes[at + 1]) << 8 | uint32_t(bytes[at + 2]) << 16 |
           uint32_t(bytes[at + 3]) << 24;
}

inline GlbFile parseGlb(const std::vector<uint8_t>& bytes) {
    if (readU32(bytes, 0) != 0x46546C67 || readU32(bytes, 4) != 2 || readU32(bytes, 8) != bytes.size()) {
        throw std::runtime_error("bad glb header");
    }
    GlbFile file;
    uint32_t jsonLength = readU32(bytes, 12);
    if (readU32(bytes, 16) != 0x4E4F534A || 20 + size_t(jsonLength) > bytes.size()) throw std::runtime_error("bad JSON chunk");
    file.json = nlohmann::json::parse(bytes.begin() + 20, bytes.begin() + 20 + jsonLength);
    size_t at = 20 + jsonLength;
    if (at < bytes.size()) {
        uint32_t binLength = readU32(bytes, at);
        if (readU32(bytes, at + 4) != 0x004E4942 || at + 8 + binLength > bytes.size()) throw std::runtime_error("bad BIN chunk");
        file.bin.assign(bytes.begin() + at + 8, bytes.begin() + at + 8 + binLength);
    }
    return file;
}

inline std::vector<uint8_t> bufferViewBytes(const GlbFile& file, size_t view) {
    const auto& v = file.json.at("bufferViews").at(view);
    size_t offset = v.value("byteOffset", size_t(0)), length = v.at("byteLength").get<size_t>();
    if (offset + length > file.bin.size()) throw std::runtime_error("bufferView beyond BIN");
    return {file.bin.begin() + offset, file.bin.begin() + offset + length};
}

/// The elements of a tightly packed plain accessor, converted to float
/// (integers unnormalised).
inline std::vector<float> readAccessor(const GlbFile& file, size_t index) {
    const auto& a = file.json.at("accessors").at(index);
    static const std::map<std::string, size_t> kComponents = {{"SCALAR", 1}, {"VEC2", 2}, {"VEC3", 3},
                                                              {"VEC4", 4}, {"MAT4", 16}};
    size_t count = a.at("count").get<size_t>() * kComponents.at(a.at("type").get<std::string>());
    std::vector<uint8_t> bytes = bufferViewBytes(file, a.at("bufferView").get<size_t>());
    int type = a.at("componentType").get<int>();
    size_t size = type == 5126 || type == 5125 ? 4 : type == 5123 ? 2 : 1;
    if (count * size > bytes.size()) throw std::runtime_error("accessor beyond its bufferView");
    std::vector<float> out(count);
    for (size_t i = 0; i < count; ++i) {
        const uint8_t* p = bytes.data() + i * size;
        if (type == 5126) std::memcpy(&out[i], p, 4);
        else if (type == 5125) out[i] = float(readU32(bytes, i * 4));
        else if (type == 5123) out[i] = float(p[0] | p[1] << 8);
        else out[i] = float(p[0]);
    }
    return out;
}

template <class Vec>
std::vector<Vec> toVectors(const std::vector<float>& flat) {
    constexpr int n = Vec::length();
    std::vector<Vec> out(flat.size() / n);
    for (size_t i = 0; i < out.size(); ++i) {
        for (int c = 0; c < n; ++c) out[i][c] = static_cast<typename Vec::value_type>(flat[i * n + c]);
    }
    return out;
}

template <class Vec>
std::vector<Vec> readDracoAttribute(const draco::Mesh& mesh, uint32_t uniqueId) {
    const draco::PointAttribute* attribute = mesh.GetAttributeByUniqueId(uniqueId);
    if (!attribute) throw std::runtime_error("Draco attribute missing");
    std::vector<Vec> out(mesh.num_points());
    for (uint32_t p = 0; p < mesh.num_points(); ++p) {
        float value[4] = {};
        attribute->ConvertValue<float>(attribute->mapped_index(draco::PointIndex(p)), Vec::length(), value);
        for (int c = 0; c < Vec::length(); ++c) out[p][c] = static_cast<typename Vec::value_type>(value[c]);
    }
    return out;
}

/// The first primitive of the first mesh.
inline GlbPrimitive readPrimitive(const GlbFile& file) {
    const auto& primitive = file.json.at("meshes").at(0).at("primitives").at(0);
    const auto& attributes = primitive.at("attributes");
    GlbPrimitive out;
    if (primitive.contains("extensions") && primitive["extensions"].contains("KHR_draco_mesh_compression")) {
        const auto& draco = primitive["extensions"]["KHR_draco_mesh_compression"];
        std::vector<uint8_t> bytes = bufferViewBytes(file, draco.at("bufferView").get<size_t>());
        draco::DecoderBuffer buffer;
        buffer.Init(reinterpret_cast<const char*>(bytes.data()), bytes.size());
        draco::Decoder decoder;
        auto decoded = decoder.DecodeMeshFromBuffer(&buffer);
        if (!decoded.ok()) throw std::runtime_error("Draco: " + decoded.status().error_msg_string());
        const draco::Mesh& mesh = *decoded.value();
        const auto& ids = draco.at("attributes");
        out.positions = readDracoAttribute<glm::vec3>(mesh, ids.at("POSITION").get<uint32_t>());
        out.normals = readDracoAttribute<glm::vec3>(mesh, ids.at("NORMAL").get<uint32_t>());
        out.tangents = readDracoAttribute<glm::vec4>(mesh, ids.at("TANGENT").get<uint32_t>());
        out.uvs = readDracoAttribute<glm::vec2>(mesh, ids.at("TEXCOORD_0").get<uint32_t>());
        out.joints = readDracoAttribute<glm::u16vec4>(mesh, ids.at("JOINTS_0").get<uint32_t>());
        out.weights = readDracoAttribute<glm::vec4>(mesh, ids.at("WEIGHTS_0").get<uint32_t>());
        for (draco::FaceIndex f(0); f < mesh.num_faces(); ++f) {
            for (int c = 0; c < 3; ++c) out.indices.push_back(mesh.face(f)[c].value());
        }
        return out;
    }
    auto read = [&](const char* name) { return readAccessor(file, attributes.at(name).get<size_t>()); };
    out.positions = toVectors<glm::vec3>(read("POSITION"));
    out.normals = toVectors<glm::vec3>(read("NORMAL"));
    out.tangents = toVectors<glm::vec4>(read("TANGENT"));
    out.uvs = toVectors<glm::vec2>(read("TEXCOORD_0"));
    out.joints = toVectors<glm::u16vec4>(read("JOINTS_0"));
    out.weights = toVectors<glm::vec4>(read("WEIGHTS_0"));
    for (float i : readAccessor(file, primitive.at("indices").get<size_t>())) out.indices.push_back(uint32_t(i));
    return out;
}

} // namespace tessera::test
