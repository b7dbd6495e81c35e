#include "GlbMeshBytes.h"

#include <nlohmann/json.hpp>

#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <vector>

namespace tessera::creature {

namespace {

uint64_t accessorBytes(const nlohmann::json& accessor) {
    static const std::map<std::string, uint64_t> kComponents = {{"SCALAR", 1}, {"VEC2", 2}, {"VEC3", 3},
                                                                {"VEC4", 4},   {"MAT4", 16}};
    uint64_t componentType = accessor.value("componentType", 5126u);
    uint64_t size = (componentType == 5120 || componentType == 5121) ? 1 : (componentType == 5122 || componentType == 5123) ? 2 : 4;
    auto it = kComponents.find(accessor.value("type", std::string("SCALAR")));
    return accessor.value("count", uint64_t{0}) * size * (it == kComponents.end() ? 1 : it->second);
}

} // namespace

Result<uint64_t> measureGlbMeshBytes(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (bytes.size() < 20 || std::memcmp(bytes.data(), "glTF", 4) != 0)
        return fail(file.string(), ": not a glb file");
    uint32_t jsonLength = 0;
    std::memcpy(&jsonLength, bytes.data() + 12, 4);
    if (20ull + jsonLength > bytes.size()) return fail(file.string(), ": truncated JSON chunk");
    nlohmann::json doc = nlohmann::json::parse(bytes.begin() + 20, bytes.begin() + 20 + jsonLength, nullptr, false);
    if (doc.is_discarded()) return fail(file.string(), ": bad JSON chunk");
    const nlohmann::json empty = nlohmann::json::array();
    auto member = [&empty](const nlohmann::json& object, const char* key) -> const nlohmann::json& {
        return object.is_object() && object.contains(key) ? object[key] : empty;
    };
    uint64_t total = 0;
    const nlohmann::json& accessors = member(doc, "accessors");
    const nlohmann::json& views = member(doc, "bufferViews");
    // Mesh 0 is the cage the exporter writes; a later mesh is the far LOD level.
    const nlohmann::json& meshes = member(doc, "meshes");
    if (meshes.is_array() && !meshes.empty()) {
        for (const auto& prim : member(meshes[0], "primitives")) {
            const nlohmann::json& draco = member(member(prim, "extensions"), "KHR_draco_mesh_compression");
            if (draco.is_object()) {
                size_t view = draco.value("bufferView", size_t{0});
                if (view < views.size()) total += views[view].value("byteLength", uint64_t{0});
                continue;
            }
            std::vector<size_t> used;
            const nlohmann::json& attributes = member(prim, "attributes");
            if (attributes.is_object())
                for (const auto& index : attributes) used.push_back(index.get<size_t>());
            if (prim.contains("indices")) used.push_back(prim["indices"].get<size_t>());
            for (size_t a : used)
                if (a < accessors.size()) total += accessorBytes(accessors[a]);
        }
    }
    return total;
}

} // namespace tessera::creature
