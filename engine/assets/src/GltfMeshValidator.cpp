#include "GltfMeshValidator.h"

#include "GltfFormats.h"

#include <algorithm>
#include <map>
#include <regex>
#include <set>

namespace tessera::assets {

namespace {

// "TEXCOORD_3" -> ("TEXCOORD", 3); "POSITION" -> ("POSITION", -1); invalid -> ("", -2).
std::pair<std::string, int> splitSemantic(const std::string& name) {
    static const std::regex indexed(R"(^(TEXCOORD|COLOR|JOINTS|WEIGHTS)_(0|[1-9][0-9]{0,3})$)");
    std::smatch m;
    if (std::regex_match(name, m, indexed)) return {m[1], std::stoi(m[2])};
    if (name == "POSITION" || name == "NORMAL" || name == "TANGENT") return {name, -1};
    if (!name.empty() && name[0] == '_') return {"_", -1};
    return {"", -2};
}

void collectTextureInfos(const Json& value, const std::string& ptr, std::vector<std::pair<std::string, int64_t>>& out) {
    if (!value.is_object()) return;
    for (auto it = value.begin(); it != value.end(); ++it) {
        const std::string& key = it.key();
        std::string p = childPointer(ptr, key);
        if (key.size() > 7 && key.compare(key.size() - 7, 7, "Texture") == 0 && it->is_object()) {
            int64_t texCoord = it->value("texCoord", int64_t{0});
            if (it->contains("extensions") && (*it)["extensions"].contains("KHR_texture_transform"))
                texCoord = (*it)["extensions"]["KHR_texture_transform"].value("texCoord", texCoord);
            out.emplace_back(p, texCoord);
        } else {
            collectTextureInfos(*it, p, out);
        }
    }
}

} // namespace

void GltfMeshValidator::validate() {
    const Json& root = mJson.root();
    bool quantized = false;
    if (root.contains("extensionsUsed"))
        for (const Json& e : root["extensionsUsed"]) quantized = quantized || e == "KHR_mesh_quantization";
    for (size_t m = 0; m < mJson.count("meshes"); ++m) {
        const Json& mesh = root["meshes"][m];
        std::string mp = childPointer("/meshes", m);
        size_t targetCount = mesh["primitives"][0].contains("targets") ? mesh["primitives"][0]["targets"].size() : 0;
        for (size_t p = 0; p < mesh["primitives"].size(); ++p) {
            const Json& primitive = mesh["primitives"][p];
            std::string pp = childPointer(mp + "/primitives", p);
            size_t targets = primitive.contains("targets") ? primitive["targets"].size() : 0;
            if (targets != targetCount) raise(pp + "/targets", "all primitives must have the same number of morph targets");
            checkPrimitive(primitive, pp, quantized);
        }
        if (mesh.contains("weights") && mesh["weights"].size() != targetCount)
            raise(mp + "/weights", "the length of weights does not match the number of morph targets");
    }
}

void GltfMeshValidator::checkAttributeFormat(const std::string& semantic, const Json& a, const std::string& ptr,
                                             bool quantized, bool morph) const {
    int64_t ct = a["componentType"].get<int64_t>();
    std::string type = a["type"].get<std::string>();
    bool normalized = a.value("normalized", false);
    bool ok = true;
    auto is = [&](int64_t c, bool n) { return ct == c && normalized == n; };
    bool anySmall = ct == kByte || ct == kUnsignedByte || ct == kShort || ct == kUnsignedShort;
    bool signedSmallNorm = (ct == kByte || ct == kShort) && normalized;
    if (semantic == "POSITION")
        ok = type == "VEC3" && (ct == kFloat || (quantized && anySmall));
    else if (semantic == "NORMAL")
        ok = type == "VEC3" && (ct == kFloat || (quantized && signedSmallNorm) || (quantized && morph && anySmall));
    else if (semantic == "TANGENT")
        ok = (morph ? type == "VEC3" : type == "VEC4") && (ct == kFloat || (quantized && signedSmallNorm));
    else if (semantic == "TEXCOORD")
        ok = type == "VEC2" && (ct == kFloat || is(kUnsignedByte, true) || is(kUnsignedShort, true) ||
                                (quantized && anySmall));
    else if (semantic == "COLOR")
        ok = (type == "VEC3" || type == "VEC4") &&
             (ct == kFloat || is(kUnsignedByte, true) || is(kUnsignedShort, true) || (morph && anySmall));
    else if (semantic == "JOINTS")
        ok = type == "VEC4" && (is(kUnsignedByte, false) || is(kUnsignedShort, false));
    else if (semantic == "WEIGHTS")
        ok = type == "VEC4" && (ct == kFloat || is(kUnsignedByte, true) || is(kUnsignedShort, true));
    else
        ok = ct != kUnsignedInt;
    if (!ok) raise(ptr, "invalid accessor format " + formatName(ct, type) + " for this attribute");
    if ((semantic == "POSITION") && (!a.contains("min") || !a.contains("max")))
        raise(ptr, "accessor.min and accessor.max must be defined for POSITION");
    if (a.contains("bufferView")) {
        const Json& view = mJson.root()["bufferViews"][a["bufferView"].get<size_t>()];
        uint64_t offset = a.value("byteOffset", uint64_t{0}) + view.value("byteOffset", uint64_t{0});
        if (offset % 4 != 0 || view.value("byteStride", uint64_t{0}) % 4 != 0)
            raise(ptr, "vertex attribute data must be aligned to 4-byte boundaries");
    }
}

void GltfMeshValidator::checkPrimitive(const Json& primitive, const std::string& ptr, bool quantized) {
    const Json& accessors = mJson.root()["accessors"];
    const Json& attributes = primitive["attributes"];
    bool draco = primitive.contains("extensions") && primitive["extensions"].contains("KHR_draco_mesh_compression");
    std::map<std::string, std::set<int>> sets;
    std::map<size_t, size_t> viewUsers;
    int64_t count = -1;
    for (auto it = attributes.begin(); it != attributes.end(); ++it) {
        std::string ap = childPointer(ptr + "/attributes", it.key());
        auto [semantic, index] = splitSemantic(it.key());
        if (index == -2) raise(ap, "invalid attribute name '" + it.key() + "'");
        sets[semantic].insert(index);
        size_t a = it->get<size_t>();
        checkAttributeFormat(semantic, accessors[a], ap, quantized, false);
        int64_t c = accessors[a]["count"].get<int64_t>();
        if (count >= 0 && c != count) raise(ap, "all accessors of a primitive must have the same count");
        count = c;
        mLayout.useAccessor(a, ap, ViewUse::Vertex);
        if (accessors[a].contains("bufferView")) {
            size_t view = accessors[a]["bufferView"].get<size_t>();
            if (++viewUsers[view] > 1 && !mJson.root()["bufferViews"][view].contains("byteStride"))
                raise(ap, "byteStride must be defined when two or more accessors use the same buffer view");
        }
    }
    if (!attributes.contains("POSITION") && !draco) raise(ptr + "/attributes", "POSITION attribute is missing");
    for (const auto& [semantic, indices] : sets)
        if (semantic != "_" && !indices.empty() && *indices.begin() >= 0 &&
            static_cast<size_t>(*indices.rbegin()) + 1 != indices.size())
            raise(ptr + "/attributes", "indexed attribute semantics of " + semantic + " must be continuous");
    if (sets["JOINTS"].size() != sets["WEIGHTS"].size())
        raise(ptr + "/attributes", "number of JOINTS attributes does not match the number of WEIGHTS");
    if (primitive.contains("indices")) {
        size_t i = primitive["indices"].get<size_t>();
        const Json& a = accessors[i];
        int64_t ct = a["componentType"].get<int64_t>();
        if (a["type"] != "SCALAR" || a.value("normalized", false) ||
            (ct != kUnsignedByte && ct != kUnsignedShort && ct != kUnsignedInt))
            raise(ptr + "/indices", "invalid indices accessor format " + formatName(ct, a["type"].get<std::string>()));
        mLayout.useAccessor(i, ptr + "/indices", ViewUse::Index);
    }
    if (primitive.contains("targets")) {
        for (size_t t = 0; t < primitive["targets"].size(); ++t) {
            const Json& target = primitive["targets"][t];
            std::string tp = childPointer(ptr + "/targets", t);
            for (auto it = target.begin(); it != target.end(); ++it) {
                std::string ap = childPointer(tp, it.key());
                auto [semantic, index] = splitSemantic(it.key());
                if (index == -2 || semantic == "JOINTS" || semantic == "WEIGHTS" || semantic == "_")
                    raise(ap, "invalid morph target attribute name '" + it.key() + "'");
                if (!attributes.contains(it.key())) raise(ap, "the primitive does not define this attribute");
                size_t a = it->get<size_t>();
                checkAttributeFormat(semantic, accessors[a], ap, quantized, true);
                if (accessors[a]["count"] != accessors[attributes[it.key()].get<size_t>()]["count"])
                    raise(ap, "morph target accessor count differs from the base accessor");
                mLayout.useAccessor(a, ap, ViewUse::Vertex);
            }
        }
    }
    checkMaterialNeeds(primitive, ptr, sets.count("TEXCOORD") ? sets["TEXCOORD"].size() : 0);
}

void GltfMeshValidator::checkMaterialNeeds(const Json& primitive, const std::string& ptr, size_t texcoordSets) const {
    if (!primitive.contains("material")) return;
    size_t m = primitive["material"].get<size_t>();
    const Json& material = mJson.root()["materials"][m];
    std::vector<std::pair<std::string, int64_t>> bindings;
    collectTextureInfos(material, childPointer("/materials", m), bindings);
    for (const auto& [binding, texCoord] : bindings)
        if (texCoord >= static_cast<int64_t>(texcoordSets))
            raise(ptr + "/material", "material texture " + binding + " uses TEXCOORD_" + std::to_string(texCoord) +
                                         " which the primitive does not have");
    const Json* ext = material.contains("extensions") ? &material["extensions"] : nullptr;
    bool needsTangents = ext && (ext->contains("KHR_materials_anisotropy") ||
                                 (ext->contains("KHR_materials_clearcoat") &&
                                  (*ext)["KHR_materials_clearcoat"].contains("clearcoatNormalTexture")));
    if (needsTangents && !primitive["attributes"].contains("TANGENT") && !material.contains("normalTexture"))
        raise(ptr + "/material", "material requires a tangent space the primitive does not provide");
}

} // namespace tessera::assets
