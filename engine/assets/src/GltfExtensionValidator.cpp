#include "GltfExtensionValidator.h"

#include <algorithm>
#include <map>
#include <regex>
#include <set>

namespace tessera::assets {

namespace {

using L = ExtensionLocation;

// The known extensions and the objects they may extend. An empty list means
// the extension never carries an object (KHR_mesh_quantization).
const std::map<std::string, std::vector<L>>& knownExtensions() {
    static const std::map<std::string, std::vector<L>> table = {
        {"KHR_draco_mesh_compression", {L::Primitive}},
        {"KHR_mesh_quantization", {}},
        {"KHR_texture_transform", {L::TextureInfo}},
        {"KHR_lights_punctual", {L::Root, L::Node}},
        {"KHR_materials_variants", {L::Root, L::Primitive}},
        {"KHR_animation_pointer", {L::AnimationTarget}},
        {"KHR_node_visibility", {L::Node}},
        {"EXT_mesh_gpu_instancing", {L::Node}},
        {"EXT_texture_webp", {L::Texture}},
        {"KHR_texture_basisu", {L::Texture}},
        {"EXT_meshopt_compression", {L::Buffer, L::BufferView}},
        {"KHR_materials_anisotropy", {L::Material}},
        {"KHR_materials_clearcoat", {L::Material}},
        {"KHR_materials_dispersion", {L::Material}},
        {"KHR_materials_emissive_strength", {L::Material}},
        {"KHR_materials_ior", {L::Material}},
        {"KHR_materials_iridescence", {L::Material}},
        {"KHR_materials_pbrSpecularGlossiness", {L::Material}},
        {"KHR_materials_sheen", {L::Material}},
        {"KHR_materials_specular", {L::Material}},
        {"KHR_materials_transmission", {L::Material}},
        {"KHR_materials_unlit", {L::Material}},
        {"KHR_materials_volume", {L::Material}},
        {"MSFT_lod", {L::Node, L::Material}},
    };
    return table;
}

constexpr double kMax = std::numeric_limits<double>::max();

} // namespace

bool isSupportedRequiredExtension(const std::string& name) {
    return name == "KHR_draco_mesh_compression" || name == "KHR_mesh_quantization";
}

void GltfExtensionValidator::checkDeclarations() const {
    const Json& root = mJson.root();
    std::set<std::string> used;
    for (const char* key : {"extensionsUsed", "extensionsRequired"}) {
        const Json* list = mJson.optArray(root, "", key);
        if (!list) continue;
        std::set<std::string> seen;
        for (size_t i = 0; i < list->size(); ++i) {
            std::string p = childPointer(std::string("/") + key, i);
            if (!(*list)[i].is_string()) raise(p, "type mismatch, expected a string");
            std::string name = (*list)[i].get<std::string>();
            if (!seen.insert(name).second) raise(p, "duplicate element '" + name + "'");
            if (std::string(key) == "extensionsUsed") {
                used.insert(name);
            } else {
                if (!root.contains("extensionsUsed"))
                    raise("/extensionsRequired", "dependency failed, 'extensionsUsed' must be defined");
                if (!used.count(name)) raise(p, "unused extension '" + name + "' cannot be required");
                if (!isSupportedRequiredExtension(name)) raise(p, "required extension '" + name + "' is not supported");
            }
        }
    }
    if (used.count("KHR_mesh_quantization")) {
        const Json* required = mJson.optArray(root, "", "extensionsRequired");
        if (!required || std::find(required->begin(), required->end(), "KHR_mesh_quantization") == required->end())
            raise("/extensionsUsed", "extension 'KHR_mesh_quantization' cannot be optional");
    }
}

void GltfExtensionValidator::check(const Json& o, const std::string& ptr, ExtensionLocation location) const {
    const Json* extensions = mJson.optObject(o, ptr, "extensions");
    if (!extensions) return;
    const Json* used = mJson.root().contains("extensionsUsed") ? &mJson.root()["extensionsUsed"] : nullptr;
    for (auto it = extensions->begin(); it != extensions->end(); ++it) {
        std::string p = childPointer(ptr + "/extensions", it.key());
        const Json& ext = mJson.asObject(it.value(), p);
        if (!used || std::find(used->begin(), used->end(), it.key()) == used->end())
            raise(p, "extension is not declared in extensionsUsed");
        auto known = knownExtensions().find(it.key());
        if (known == knownExtensions().end()) continue;
        const auto& where = known->second;
        if (std::find(where.begin(), where.end(), location) == where.end())
            raise(p, "unexpected location for this extension");
        checkContent(it.key(), ext, p, o, location);
    }
}

void GltfExtensionValidator::checkTextureInfo(const Json& o, const std::string& ptr) const {
    mJson.reqIndex(o, ptr, "index", "textures");
    mJson.optInt(o, ptr, "texCoord");
    check(o, ptr, L::TextureInfo);
}

void GltfExtensionValidator::checkContent(const std::string& name, const Json& ext, const std::string& ptr,
                                          const Json& owner, ExtensionLocation location) const {
    const Json& root = mJson.root();
    if (name == "KHR_lights_punctual") {
        if (&owner == &root) return checkLights(ext, ptr);
        const Json* rootExt = root.contains("extensions") ? &root["extensions"] : nullptr;
        if (!rootExt || !rootExt->contains(name))
            raise(ptr, "dependency failed, '/extensions/KHR_lights_punctual' must be defined");
        if (!ext.contains("light")) raise(ptr, "required property 'light' is missing");
        const Json& lights = (*rootExt)[name];
        size_t count = lights.contains("lights") && lights["lights"].is_array() ? lights["lights"].size() : 0;
        mJson.checkIndex(ext["light"], ptr + "/light", count);
    } else if (name == "KHR_materials_variants") {
        if (&owner == &root) return checkVariantsRoot(ext, ptr);
        checkVariantsPrimitive(ext, ptr);
    } else if (name == "KHR_animation_pointer") {
        static const std::regex pointer(R"(^(?:\/(?:[^/~]|~0|~1)*)*$)");
        std::string value = mJson.reqString(ext, ptr, "pointer");
        if (!std::regex_match(value, pointer)) raise(ptr + "/pointer", "'" + value + "' is not a JSON pointer");
        if (owner.contains("node")) raise(ptr, "this extension requires the channel target node to be undefined");
        if (owner.value("path", Json()) != "pointer") raise(ptr, "this extension requires the target path 'pointer'");
    } else if (name == "KHR_draco_mesh_compression") {
        mJson.reqIndex(ext, ptr, "bufferView", "bufferViews");
        const Json& attributes = mJson.reqObject(ext, ptr, "attributes");
        for (auto it = attributes.begin(); it != attributes.end(); ++it)
            mJson.checkIndex(it.value(), childPointer(ptr + "/attributes", it.key()), 1u << 30);
    } else if (name == "KHR_texture_transform") {
        mJson.optNumbers(ext, ptr, "offset", 2);
        mJson.optNumbers(ext, ptr, "scale", 2);
        mJson.optNumber(ext, ptr, "rotation");
        mJson.optInt(ext, ptr, "texCoord");
    } else if (name == "EXT_texture_webp" || name == "KHR_texture_basisu") {
        mJson.reqIndex(ext, ptr, "source", "images");
    } else if (name == "KHR_node_visibility") {
        mJson.optBool(ext, ptr, "visible");
    } else if (name == "MSFT_lod") {
        checkLod(ext, ptr, owner, location);
    } else if (name.rfind("KHR_materials_", 0) == 0) {
        checkMaterialExtension(name, ext, ptr);
    }
}

void GltfExtensionValidator::checkLod(const Json& ext, const std::string& ptr, const Json& owner,
                                      ExtensionLocation location) const {
    // MSFT_lod: `ids` lists the lower levels, other nodes (or materials) of
    // the same kind as the owner, from the next lower level to the lowest.
    const char* collection = location == L::Node ? "nodes" : "materials";
    const Json& ids = mJson.reqArray(ext, ptr, "ids");
    size_t count = mJson.count(collection);
    std::set<size_t> seen;
    for (size_t i = 0; i < ids.size(); ++i) {
        std::string p = childPointer(ptr + "/ids", i);
        size_t id = mJson.checkIndex(ids[i], p, count);
        if (!seen.insert(id).second) raise(p, "duplicate element " + std::to_string(id));
        // The owner is an element of the same array: a level cannot be itself.
        if (&mJson.root().at(collection).at(id) == &owner) raise(p, "a level of detail cannot refer to its own object");
    }
}

void GltfExtensionValidator::checkLights(const Json& ext, const std::string& ptr) const {
    const Json& lights = mJson.reqArray(ext, ptr, "lights");
    for (size_t i = 0; i < lights.size(); ++i) {
        std::string p = childPointer(ptr + "/lights", i);
        const Json& light = mJson.asObject(lights[i], p);
        if (!light.contains("type")) raise(p, "required property 'type' is missing");
        auto type = mJson.optEnum(light, p, "type", {"directional", "point", "spot"});
        mJson.optNumbers(light, p, "color", 3, 0.0, 1.0);
        mJson.optNumber(light, p, "intensity", 0.0);
        mJson.optNumber(light, p, "range", 0.0, kMax, true);
        if (*type == "spot") {
            const Json& spot = mJson.reqObject(light, p, "spot");
            double inner = mJson.optNumber(spot, p + "/spot", "innerConeAngle", 0.0, 1.5707963267948966).value_or(0.0);
            double outer = mJson.optNumber(spot, p + "/spot", "outerConeAngle", 0.0, 1.5707963267948966, true)
                               .value_or(0.7853981633974483);
            if (outer <= inner) raise(p + "/spot/outerConeAngle", "outerConeAngle is not greater than innerConeAngle");
        }
    }
}

void GltfExtensionValidator::checkVariantsRoot(const Json& ext, const std::string& ptr) const {
    const Json& variants = mJson.reqArray(ext, ptr, "variants");
    for (size_t i = 0; i < variants.size(); ++i) {
        std::string p = childPointer(ptr + "/variants", i);
        mJson.reqString(mJson.asObject(variants[i], p), p, "name");
    }
}

void GltfExtensionValidator::checkVariantsPrimitive(const Json& ext, const std::string& ptr) const {
    const Json& root = mJson.root();
    const Json& mappings = mJson.reqArray(ext, ptr, "mappings");
    const Json* rootExt = root.contains("extensions") && root["extensions"].contains("KHR_materials_variants")
                              ? &root["extensions"]["KHR_materials_variants"] : nullptr;
    size_t variantCount = rootExt && rootExt->contains("variants") && (*rootExt)["variants"].is_array()
                              ? (*rootExt)["variants"].size() : 0;
    std::set<size_t> seen;
    for (size_t i = 0; i < mappings.size(); ++i) {
        std::string p = childPointer(ptr + "/mappings", i);
        const Json& mapping = mJson.asObject(mappings[i], p);
        if (!rootExt) raise(p, "dependency failed, '/extensions/KHR_materials_variants' must be defined");
        const Json& variants = mJson.reqArray(mapping, p, "variants");
        for (size_t v = 0; v < variants.size(); ++v) {
            size_t index = mJson.checkIndex(variants[v], childPointer(p + "/variants", v), variantCount);
            if (!seen.insert(index).second) raise(childPointer(p + "/variants", v), "variant used more than once");
        }
        mJson.reqIndex(mapping, p, "material", "materials");
    }
}

void GltfExtensionValidator::checkMaterialExtension(const std::string& name, const Json& ext,
                                                    const std::string& ptr) const {
    // Factors in [0, 1] unless listed otherwise; every *Texture is a textureInfo.
    for (auto it = ext.begin(); it != ext.end(); ++it) {
        const std::string& key = it.key();
        if (key.size() > 7 && key.compare(key.size() - 7, 7, "Texture") == 0) {
            checkTextureInfo(mJson.asObject(it.value(), childPointer(ptr, key)), childPointer(ptr, key));
        }
    }
    const char* unitFactors[] = {"anisotropyStrength", "clearcoatFactor", "clearcoatRoughnessFactor",
                                 "iridescenceFactor", "glossinessFactor", "sheenRoughnessFactor",
                                 "specularFactor", "transmissionFactor"};
    bool specGloss = name == "KHR_materials_pbrSpecularGlossiness";
    for (const char* key : unitFactors)
        if (!(specGloss && std::string(key) == "specularFactor")) mJson.optNumber(ext, ptr, key, 0.0, 1.0);
    for (const char* key : {"dispersion", "emissiveStrength", "thicknessFactor", "iridescenceThicknessMinimum",
                            "iridescenceThicknessMaximum"})
        mJson.optNumber(ext, ptr, key, 0.0);
    mJson.optNumber(ext, ptr, "attenuationDistance", 0.0, kMax, true);
    mJson.optNumber(ext, ptr, "iridescenceIor", 1.0);
    mJson.optNumbers(ext, ptr, "attenuationColor", 3, 0.0, 1.0);
    mJson.optNumbers(ext, ptr, "sheenColorFactor", 3, 0.0, 1.0);
    mJson.optNumbers(ext, ptr, "specularColorFactor", 3, 0.0);
    if (specGloss) {
        mJson.optNumbers(ext, ptr, "diffuseFactor", 4, 0.0, 1.0);
        mJson.optNumbers(ext, ptr, "specularFactor", 3, 0.0, 1.0);
    }
    if (auto ior = mJson.optNumber(ext, ptr, "ior", 0.0); ior && *ior != 0.0 && *ior < 1.0)
        raise(ptr + "/ior", "value " + std::to_string(*ior) + " is out of range");
}

} // namespace tessera::assets
