#include "GltfSchemaValidator.h"

#include <cmath>
#include <regex>

namespace tessera::assets {

namespace {

// Each root collection, its object checker, and where its extensions belong.
using Checker = void (GltfSchemaValidator::*)(const Json&, const std::string&) const;

const std::vector<std::string> kAccessorTypes = {"SCALAR", "VEC2", "VEC3", "VEC4", "MAT2", "MAT3", "MAT4"};

} // namespace

void GltfSchemaValidator::checkCommon(const Json& o, const std::string& ptr, ExtensionLocation location) const {
    mJson.optString(o, ptr, "name");
    mExtensions.check(o, ptr, location);
}

void GltfSchemaValidator::validate() const {
    const Json& root = mJson.asObject(mJson.root(), "");
    checkAsset(mJson.reqObject(root, "", "asset"));
    mExtensions.checkDeclarations();
    checkCommon(root, "", ExtensionLocation::Root);

    struct Collection { const char* name; Checker check; };
    const Collection collections[] = {
        {"buffers", &GltfSchemaValidator::checkBuffer}, {"bufferViews", &GltfSchemaValidator::checkBufferView},
        {"accessors", &GltfSchemaValidator::checkAccessor}, {"meshes", &GltfSchemaValidator::checkMesh},
        {"nodes", &GltfSchemaValidator::checkNode}, {"skins", &GltfSchemaValidator::checkSkin},
        {"animations", &GltfSchemaValidator::checkAnimation}, {"cameras", &GltfSchemaValidator::checkCamera},
        {"images", &GltfSchemaValidator::checkImage}, {"textures", &GltfSchemaValidator::checkTexture},
        {"samplers", &GltfSchemaValidator::checkSampler}, {"materials", &GltfSchemaValidator::checkMaterial},
        {"scenes", &GltfSchemaValidator::checkScene},
    };
    for (const Collection& c : collections) {
        const Json* array = mJson.optArray(root, "", c.name);
        if (!array) continue;
        for (size_t i = 0; i < array->size(); ++i) {
            std::string ptr = childPointer(std::string("/") + c.name, i);
            (this->*c.check)(mJson.asObject((*array)[i], ptr), ptr);
        }
    }
    mJson.optIndex(root, "", "scene", "scenes");
}

void GltfSchemaValidator::checkAsset(const Json& asset) const {
    const std::string ptr = "/asset";
    static const std::regex version(R"(^([0-9]+)\.([0-9]+)$)");
    std::string v = mJson.reqString(asset, ptr, "version");
    std::smatch m;
    if (!std::regex_match(v, m, version)) raise(ptr + "/version", "'" + v + "' is not a MAJOR.MINOR version");
    if (m[1] != "2") raise(ptr + "/version", "unknown glTF major version " + m[1].str() + " (only 2.x is supported)");
    if (auto minVersion = mJson.optString(asset, ptr, "minVersion")) {
        std::smatch mm;
        if (!std::regex_match(*minVersion, mm, version))
            raise(ptr + "/minVersion", "'" + *minVersion + "' is not a MAJOR.MINOR version");
        if (std::stoll(mm[1]) != 2 || std::stoll(mm[2]) > std::stoll(m[2]))
            raise(ptr + "/minVersion", "minVersion " + *minVersion + " is greater than version " + v);
    }
    mJson.optString(asset, ptr, "generator");
    mJson.optString(asset, ptr, "copyright");
    checkCommon(asset, ptr, ExtensionLocation::Asset);
}

void GltfSchemaValidator::checkBuffer(const Json& o, const std::string& ptr) const {
    mJson.optString(o, ptr, "uri");
    mJson.reqInt(o, ptr, "byteLength", 1);
    checkCommon(o, ptr, ExtensionLocation::Buffer);
}

void GltfSchemaValidator::checkBufferView(const Json& o, const std::string& ptr) const {
    mJson.reqIndex(o, ptr, "buffer", "buffers");
    mJson.optInt(o, ptr, "byteOffset");
    mJson.reqInt(o, ptr, "byteLength", 1);
    if (auto stride = mJson.optInt(o, ptr, "byteStride", 4, 252); stride && *stride % 4 != 0)
        raise(ptr + "/byteStride", "value " + std::to_string(*stride) + " is not a multiple of 4");
    mJson.optIntEnum(o, ptr, "target", {34962, 34963});
    checkCommon(o, ptr, ExtensionLocation::BufferView);
}

void GltfSchemaValidator::checkAccessor(const Json& o, const std::string& ptr) const {
    mJson.optIndex(o, ptr, "bufferView", "bufferViews");
    mJson.optInt(o, ptr, "byteOffset");
    mJson.requireWith(o, ptr, "byteOffset", "bufferView");
    if (!o.contains("componentType")) raise(ptr, "required property 'componentType' is missing");
    mJson.optIntEnum(o, ptr, "componentType", {5120, 5121, 5122, 5123, 5125, 5126});
    mJson.optBool(o, ptr, "normalized");
    mJson.reqInt(o, ptr, "count", 1);
    if (!o.contains("type")) raise(ptr, "required property 'type' is missing");
    mJson.optEnum(o, ptr, "type", kAccessorTypes);
    mJson.optNumbers(o, ptr, "max", 0);
    mJson.optNumbers(o, ptr, "min", 0);
    if (const Json* sparse = mJson.optObject(o, ptr, "sparse")) {
        std::string sp = ptr + "/sparse";
        mJson.reqInt(*sparse, sp, "count", 1);
        const Json& indices = mJson.reqObject(*sparse, sp, "indices");
        mJson.reqIndex(indices, sp + "/indices", "bufferView", "bufferViews");
        mJson.optInt(indices, sp + "/indices", "byteOffset");
        if (!indices.contains("componentType")) raise(sp + "/indices", "required property 'componentType' is missing");
        mJson.optIntEnum(indices, sp + "/indices", "componentType", {5121, 5123, 5125});
        checkCommon(indices, sp + "/indices", ExtensionLocation::Other);
        const Json& values = mJson.reqObject(*sparse, sp, "values");
        mJson.reqIndex(values, sp + "/values", "bufferView", "bufferViews");
        mJson.optInt(values, sp + "/values", "byteOffset");
        checkCommon(values, sp + "/values", ExtensionLocation::Other);
        checkCommon(*sparse, sp, ExtensionLocation::Other);
    }
    checkCommon(o, ptr, ExtensionLocation::Accessor);
}

void GltfSchemaValidator::checkMesh(const Json& o, const std::string& ptr) const {
    const Json& primitives = mJson.reqArray(o, ptr, "primitives");
    for (size_t i = 0; i < primitives.size(); ++i) {
        std::string pp = childPointer(ptr + "/primitives", i);
        const Json& p = mJson.asObject(primitives[i], pp);
        const Json& attributes = mJson.reqObject(p, pp, "attributes");
        if (attributes.empty()) raise(pp + "/attributes", "object cannot be empty");
        for (auto it = attributes.begin(); it != attributes.end(); ++it)
            mJson.checkIndex(it.value(), childPointer(pp + "/attributes", it.key()), mJson.count("accessors"));
        mJson.optIndex(p, pp, "indices", "accessors");
        mJson.optIndex(p, pp, "material", "materials");
        mJson.optInt(p, pp, "mode", 0, 6);
        if (const Json* targets = mJson.optArray(p, pp, "targets")) {
            for (size_t t = 0; t < targets->size(); ++t) {
                std::string tp = childPointer(pp + "/targets", t);
                const Json& target = mJson.asObject((*targets)[t], tp);
                if (target.empty()) raise(tp, "object cannot be empty");
                for (auto it = target.begin(); it != target.end(); ++it)
                    mJson.checkIndex(it.value(), childPointer(tp, it.key()), mJson.count("accessors"));
            }
        }
        checkCommon(p, pp, ExtensionLocation::Primitive);
    }
    mJson.optNumbers(o, ptr, "weights", 0);
    checkCommon(o, ptr, ExtensionLocation::Mesh);
}

void GltfSchemaValidator::checkNode(const Json& o, const std::string& ptr) const {
    mJson.optIndex(o, ptr, "camera", "cameras");
    mJson.indexArray(o, ptr, "children", "nodes", false);
    mJson.requireWith(o, ptr, "skin", "mesh");
    mJson.optIndex(o, ptr, "skin", "skins");
    mJson.optIndex(o, ptr, "mesh", "meshes");
    mJson.requireWith(o, ptr, "weights", "mesh");
    mJson.optNumbers(o, ptr, "matrix", 16);
    mJson.optNumbers(o, ptr, "rotation", 4, -1.0, 1.0);
    mJson.optNumbers(o, ptr, "scale", 3);
    mJson.optNumbers(o, ptr, "translation", 3);
    mJson.optNumbers(o, ptr, "weights", 0);
    checkCommon(o, ptr, ExtensionLocation::Node);
}

void GltfSchemaValidator::checkSkin(const Json& o, const std::string& ptr) const {
    mJson.optIndex(o, ptr, "inverseBindMatrices", "accessors");
    mJson.optIndex(o, ptr, "skeleton", "nodes");
    mJson.indexArray(o, ptr, "joints", "nodes", true);
    checkCommon(o, ptr, ExtensionLocation::Skin);
}

void GltfSchemaValidator::checkAnimation(const Json& o, const std::string& ptr) const {
    bool hasChannels = o.contains("channels"), hasSamplers = o.contains("samplers");
    if (!hasChannels) raise(ptr, "required property 'channels' is missing");
    if (!hasSamplers) raise(ptr, "required property 'samplers' is missing");
    const Json& samplers = mJson.reqArray(o, ptr, "samplers");
    const Json& channels = mJson.reqArray(o, ptr, "channels");
    for (size_t i = 0; i < samplers.size(); ++i) {
        std::string sp = childPointer(ptr + "/samplers", i);
        const Json& s = mJson.asObject(samplers[i], sp);
        mJson.reqIndex(s, sp, "input", "accessors");
        mJson.reqIndex(s, sp, "output", "accessors");
        mJson.optEnum(s, sp, "interpolation", {"LINEAR", "STEP", "CUBICSPLINE"});
        checkCommon(s, sp, ExtensionLocation::AnimationSampler);
    }
    for (size_t i = 0; i < channels.size(); ++i) {
        std::string cp = childPointer(ptr + "/channels", i);
        const Json& c = mJson.asObject(channels[i], cp);
        if (!c.contains("sampler")) raise(cp, "required property 'sampler' is missing");
        mJson.checkIndex(c["sampler"], cp + "/sampler", samplers.size());
        const Json& target = mJson.reqObject(c, cp, "target");
        mJson.optIndex(target, cp + "/target", "node", "nodes");
        if (!target.contains("path")) raise(cp + "/target", "required property 'path' is missing");
        mJson.optString(target, cp + "/target", "path");
        checkCommon(target, cp + "/target", ExtensionLocation::AnimationTarget);
        checkCommon(c, cp, ExtensionLocation::AnimationChannel);
    }
    checkCommon(o, ptr, ExtensionLocation::Animation);
}

void GltfSchemaValidator::checkCamera(const Json& o, const std::string& ptr) const {
    if (!o.contains("type")) raise(ptr, "required property 'type' is missing");
    std::string type = *mJson.optEnum(o, ptr, "type", {"perspective", "orthographic"});
    if (o.contains("perspective") == o.contains("orthographic"))
        raise(ptr, "exactly one of 'orthographic' and 'perspective' must be defined");
    if (!o.contains(type)) raise(ptr, "required property '" + type + "' is missing");
    std::string cp = ptr + "/" + type;
    const Json& c = mJson.reqObject(o, ptr, type.c_str());
    if (type == "perspective") {
        mJson.optNumber(c, cp, "aspectRatio", 0.0, std::numeric_limits<double>::max(), true);
        mJson.reqNumber(c, cp, "yfov", 0.0, std::numeric_limits<double>::max(), true);
        double znear = mJson.reqNumber(c, cp, "znear", 0.0, std::numeric_limits<double>::max(), true);
        if (auto zfar = mJson.optNumber(c, cp, "zfar", 0.0, std::numeric_limits<double>::max(), true);
            zfar && *zfar <= znear)
            raise(cp, "zfar must be greater than znear");
    } else {
        double xmag = mJson.reqNumber(c, cp, "xmag"), ymag = mJson.reqNumber(c, cp, "ymag");
        if (xmag == 0.0 || ymag == 0.0) raise(cp, "xmag and ymag must not be zero");
        double znear = mJson.reqNumber(c, cp, "znear", 0.0);
        if (mJson.reqNumber(c, cp, "zfar", 0.0, std::numeric_limits<double>::max(), true) <= znear)
            raise(cp, "zfar must be greater than znear");
    }
    checkCommon(c, cp, ExtensionLocation::Other);
    checkCommon(o, ptr, ExtensionLocation::Camera);
}

void GltfSchemaValidator::checkImage(const Json& o, const std::string& ptr) const {
    if (o.contains("uri") == o.contains("bufferView")) raise(ptr, "exactly one of 'bufferView' and 'uri' must be defined");
    mJson.optString(o, ptr, "uri");
    mJson.optIndex(o, ptr, "bufferView", "bufferViews");
    auto mime = mJson.optString(o, ptr, "mimeType");
    if (o.contains("bufferView") && !mime) raise(ptr + "/bufferView", "dependency failed, 'mimeType' must be defined");
    checkCommon(o, ptr, ExtensionLocation::Image);
}

void GltfSchemaValidator::checkTexture(const Json& o, const std::string& ptr) const {
    mJson.optIndex(o, ptr, "sampler", "samplers");
    mJson.optIndex(o, ptr, "source", "images");
    checkCommon(o, ptr, ExtensionLocation::Texture);
}

void GltfSchemaValidator::checkSampler(const Json& o, const std::string& ptr) const {
    mJson.optIntEnum(o, ptr, "magFilter", {9728, 9729});
    mJson.optIntEnum(o, ptr, "minFilter", {9728, 9729, 9984, 9985, 9986, 9987});
    mJson.optIntEnum(o, ptr, "wrapS", {33071, 33648, 10497});
    mJson.optIntEnum(o, ptr, "wrapT", {33071, 33648, 10497});
    checkCommon(o, ptr, ExtensionLocation::Sampler);
}

void GltfSchemaValidator::checkMaterial(const Json& o, const std::string& ptr) const {
    if (const Json* pbr = mJson.optObject(o, ptr, "pbrMetallicRoughness")) {
        std::string pp = ptr + "/pbrMetallicRoughness";
        mJson.optNumbers(*pbr, pp, "baseColorFactor", 4, 0.0, 1.0);
        mJson.optNumber(*pbr, pp, "metallicFactor", 0.0, 1.0);
        mJson.optNumber(*pbr, pp, "roughnessFactor", 0.0, 1.0);
        for (const char* key : {"baseColorTexture", "metallicRoughnessTexture"})
            if (const Json* t = mJson.optObject(*pbr, pp, key)) mExtensions.checkTextureInfo(*t, pp + "/" + key);
        checkCommon(*pbr, pp, ExtensionLocation::Other);
    }
    for (const char* key : {"normalTexture", "occlusionTexture", "emissiveTexture"})
        if (const Json* t = mJson.optObject(o, ptr, key)) mExtensions.checkTextureInfo(*t, ptr + "/" + key);
    if (const Json* t = mJson.optObject(o, ptr, "normalTexture")) mJson.optNumber(*t, ptr + "/normalTexture", "scale");
    if (const Json* t = mJson.optObject(o, ptr, "occlusionTexture"))
        mJson.optNumber(*t, ptr + "/occlusionTexture", "strength", 0.0, 1.0);
    mJson.optNumbers(o, ptr, "emissiveFactor", 3, 0.0, 1.0);
    mJson.optEnum(o, ptr, "alphaMode", {"OPAQUE", "MASK", "BLEND"});
    mJson.optNumber(o, ptr, "alphaCutoff", 0.0);
    mJson.optBool(o, ptr, "doubleSided");
    checkCommon(o, ptr, ExtensionLocation::Material);
}

void GltfSchemaValidator::checkScene(const Json& o, const std::string& ptr) const {
    mJson.indexArray(o, ptr, "nodes", "nodes", false);
    checkCommon(o, ptr, ExtensionLocation::Scene);
}

} // namespace tessera::assets
