#include "LodReader.h"

#include "GltfError.h"
#include "MeshConverter.h"

#include <string>

namespace tessera::assets {

namespace {

std::string skinName(int skin) { return skin < 0 ? std::string("no skin") : "skin " + std::to_string(skin); }

// The LOD node the entry `ids[k]` of `node`'s MSFT_lod names, checked against
// what the far tier needs. The extension validator already checked the ids'
// types and range; these checks hold on their own all the same, so a model
// built some other way cannot index out of range.
int checkLevel(const tinygltf::Model& model, const SkeletonBuild& skeleton, int node, const nlohmann::json& id,
               const std::string& ptr) {
    if (!id.is_number_integer() || id.get<int64_t>() < 0 || id.get<int64_t>() >= static_cast<int64_t>(model.nodes.size()))
        raise(ptr, "MSFT_lod level " + id.dump() + " is not a node index (the file has " +
                       std::to_string(model.nodes.size()) + " nodes)");
    const int lod = static_cast<int>(id.get<int64_t>());
    const tinygltf::Node& base = model.nodes[static_cast<size_t>(node)];
    const tinygltf::Node& level = model.nodes[static_cast<size_t>(lod)];
    if (lod == node) raise(ptr, "MSFT_lod level " + std::to_string(lod) + " is the node itself");
    // A level inside the scene would also be merged into the cage.
    if (skeleton.nodeToIndex.count(lod))
        raise(ptr, "MSFT_lod level node " + std::to_string(lod) + " is part of the scene; a level must be outside it");
    if (level.mesh < 0) raise(ptr, "MSFT_lod level node " + std::to_string(lod) + " has no mesh");
    if (level.skin != base.skin)
        raise(ptr, "MSFT_lod level node " + std::to_string(lod) + " has " + skinName(level.skin) +
                       ", not the " + skinName(base.skin) + " of node " + std::to_string(node) +
                       " (the far mesh must use the same skinning palette)");
    return lod;
}

bool sameBindings(const std::vector<character::SkinBinding>& a, const std::vector<character::SkinBinding>& b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i) {
        if (a[i].node != b[i].node || a[i].inverseBind != b[i].inverseBind) return false;
    }
    return true;
}

} // namespace

std::optional<character::CageMesh> readFarLod(const tinygltf::Model& model, const nlohmann::json& json,
                                              const SkeletonBuild& skeleton, const character::CageMesh& cage) {
    int meshNodes = 0;
    int farNode = -1;       // the lowest level of the one mesh node, if any
    uint32_t baseIndex = 0;  // that mesh node's skeleton index
    const nlohmann::json* nodes = json.contains("nodes") && json["nodes"].is_array() ? &json["nodes"] : nullptr;
    for (size_t s = 0; s < skeleton.indexToNode.size(); ++s) {
        const int node = skeleton.indexToNode[s];
        if (model.nodes[static_cast<size_t>(node)].mesh < 0) continue;
        ++meshNodes;
        if (!nodes || static_cast<size_t>(node) >= nodes->size()) continue;
        const nlohmann::json& n = (*nodes)[static_cast<size_t>(node)];
        if (!n.is_object() || !n.contains("extensions") || !n["extensions"].is_object() ||
            !n["extensions"].contains("MSFT_lod"))
            continue;
        const std::string ptr = "/nodes/" + std::to_string(node) + "/extensions/MSFT_lod/ids";
        const nlohmann::json& lod = n["extensions"]["MSFT_lod"];
        if (!lod.is_object() || !lod.contains("ids") || !lod["ids"].is_array() || lod["ids"].empty())
            raise(ptr, "MSFT_lod needs a non-empty array of node indices");
        const nlohmann::json& ids = lod["ids"];
        for (size_t k = 0; k < ids.size(); ++k) {
            farNode = checkLevel(model, skeleton, node, ids[k], ptr + "/" + std::to_string(k));
        }
        baseIndex = static_cast<uint32_t>(s);
    }
    if (meshNodes != 1 || farNode < 0) return std::nullopt;

    MeshConverter converter(model, skeleton);
    character::CageMesh far = converter.convertNode(farNode, baseIndex);
    // Same skin, so the same palette; checked all the same, because the
    // renderer indexes the cage's palette with the far mesh's joints.
    if (!sameBindings(far.bindings, cage.bindings))
        raise("/nodes/" + std::to_string(farNode), "the MSFT_lod level's skinning palette differs from the cage's");
    return far;
}

} // namespace tessera::assets
