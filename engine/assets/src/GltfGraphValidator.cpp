#include "GltfGraphValidator.h"

#include "GltfFormats.h"

#include <cmath>
#include <set>

namespace tessera::assets {

void GltfGraphValidator::validate() {
    checkNodes();
    checkSkins();
    checkAnimations();
    checkImages();
}

size_t GltfGraphValidator::rootOf(size_t node) const {
    while (mParent[node] >= 0) node = static_cast<size_t>(mParent[node]);
    return node;
}

size_t GltfGraphValidator::morphTargetCount(const Json& node) const {
    if (!node.contains("mesh")) return 0;
    const Json& primitive = mJson.root()["meshes"][node["mesh"].get<size_t>()]["primitives"][0];
    return primitive.contains("targets") ? primitive["targets"].size() : 0;
}

void GltfGraphValidator::checkNodeTransform(const Json& node, const std::string& ptr) const {
    if (node.contains("matrix")) {
        if (node.contains("translation") || node.contains("rotation") || node.contains("scale"))
            raise(ptr + "/matrix", "a node can have either a matrix or translation/rotation/scale");
        const Json& m = node["matrix"];
        auto at = [&](int i) { return m[static_cast<size_t>(i)].get<double>(); };
        bool affine = at(3) == 0.0 && at(7) == 0.0 && at(11) == 0.0 && at(15) == 1.0;
        double columns[3][3];
        for (int c = 0; c < 3; ++c) {
            double len = std::sqrt(at(c * 4) * at(c * 4) + at(c * 4 + 1) * at(c * 4 + 1) + at(c * 4 + 2) * at(c * 4 + 2));
            for (int r = 0; r < 3; ++r) columns[c][r] = len > 0.0 ? at(c * 4 + r) / len : 0.0;
        }
        auto dot = [&](int a, int b) {
            return columns[a][0] * columns[b][0] + columns[a][1] * columns[b][1] + columns[a][2] * columns[b][2];
        };
        bool orthogonal = std::fabs(dot(0, 1)) < 1e-4 && std::fabs(dot(0, 2)) < 1e-4 && std::fabs(dot(1, 2)) < 1e-4;
        if (!affine || !orthogonal) raise(ptr + "/matrix", "matrix must be decomposable to translation/rotation/scale");
    }
    if (node.contains("rotation")) {
        double len2 = 0.0;
        for (const Json& v : node["rotation"]) len2 += v.get<double>() * v.get<double>();
        if (std::fabs(std::sqrt(len2) - 1.0) > 5e-4) raise(ptr + "/rotation", "rotation quaternion must be normalized");
    }
}

void GltfGraphValidator::checkNodes() {
    const Json& root = mJson.root();
    size_t count = mJson.count("nodes");
    mParent.assign(count, -1);
    for (size_t n = 0; n < count; ++n) {
        const Json& node = root["nodes"][n];
        std::string ptr = childPointer("/nodes", n);
        checkNodeTransform(node, ptr);
        if (node.contains("children"))
            for (size_t c = 0; c < node["children"].size(); ++c) {
                size_t child = node["children"][c].get<size_t>();
                if (mParent[child] >= 0 || child == n)
                    raise(childPointer(ptr + "/children", c), "node " + std::to_string(child) + " has more than one parent");
                mParent[child] = static_cast<int64_t>(n);
            }
        if (node.contains("weights") && node["weights"].size() != morphTargetCount(node))
            raise(ptr + "/weights", "the length of weights does not match the number of morph targets");
        if (node.contains("skin")) {
            const Json& primitives = root["meshes"][node["mesh"].get<size_t>()]["primitives"];
            for (const Json& p : primitives)
                if (!p["attributes"].contains("JOINTS_0")) raise(ptr, "node has a skin but its mesh has no joints data");
        }
    }
    for (size_t n = 0; n < count; ++n) {
        size_t steps = 0;
        for (int64_t p = mParent[n]; p >= 0; p = mParent[static_cast<size_t>(p)])
            if (++steps > count) raise(childPointer("/nodes", n), "node is part of a node loop");
    }
    for (size_t s = 0; s < mJson.count("scenes"); ++s) {
        const Json& scene = root["scenes"][s];
        if (!scene.contains("nodes")) continue;
        for (size_t i = 0; i < scene["nodes"].size(); ++i)
            if (mParent[scene["nodes"][i].get<size_t>()] >= 0)
                raise(childPointer(childPointer("/scenes", s) + "/nodes", i), "node is not a root node");
    }
}

void GltfGraphValidator::checkSkins() {
    const Json& root = mJson.root();
    for (size_t s = 0; s < mJson.count("skins"); ++s) {
        const Json& skin = root["skins"][s];
        std::string ptr = childPointer("/skins", s);
        const Json& joints = skin["joints"];
        size_t commonRoot = rootOf(joints[0].get<size_t>());
        for (const Json& j : joints)
            if (rootOf(j.get<size_t>()) != commonRoot) raise(ptr + "/joints", "joints do not have a common root");
        if (skin.contains("skeleton")) {
            size_t skeleton = skin["skeleton"].get<size_t>();
            for (const Json& j : joints) {
                int64_t n = static_cast<int64_t>(j.get<size_t>());
                while (n >= 0 && static_cast<size_t>(n) != skeleton) n = mParent[static_cast<size_t>(n)];
                if (n < 0) raise(ptr + "/skeleton", "skeleton node is not a common root of the joints");
            }
        }
        if (skin.contains("inverseBindMatrices")) {
            size_t a = skin["inverseBindMatrices"].get<size_t>();
            const Json& accessor = root["accessors"][a];
            if (accessor["type"] != "MAT4" || accessor["componentType"] != kFloat)
                raise(ptr + "/inverseBindMatrices", "inverse bind matrices must be {MAT4, FLOAT}");
            if (accessor["count"].get<size_t>() < joints.size())
                raise(ptr + "/inverseBindMatrices", "accessor must have at least " + std::to_string(joints.size()) +
                                                        " elements");
            mLayout.useAccessor(a, ptr + "/inverseBindMatrices", ViewUse::Other);
        }
    }
    // A skinned node's scene must contain its joints.
    for (size_t s = 0; s < mJson.count("scenes"); ++s) {
        const Json& scene = root["scenes"][s];
        if (!scene.contains("nodes")) continue;
        std::set<size_t> roots;
        for (const Json& n : scene["nodes"]) roots.insert(n.get<size_t>());
        for (size_t n = 0; n < mJson.count("nodes"); ++n) {
            const Json& node = root["nodes"][n];
            if (!node.contains("skin") || !roots.count(rootOf(n))) continue;
            size_t joint = root["skins"][node["skin"].get<size_t>()]["joints"][0].get<size_t>();
            if (!roots.count(rootOf(joint)))
                raise(childPointer("/nodes", n), "skinned mesh is used in a scene that does not contain its joints");
        }
    }
}

void GltfGraphValidator::checkAnimations() {
    const Json& root = mJson.root();
    for (size_t an = 0; an < mJson.count("animations"); ++an) {
        const Json& animation = root["animations"][an];
        std::string ptr = childPointer("/animations", an);
        std::set<std::pair<size_t, std::string>> targets;
        for (size_t c = 0; c < animation["channels"].size(); ++c) {
            const Json& channel = animation["channels"][c];
            std::string cp = childPointer(ptr + "/channels", c);
            const Json& target = channel["target"];
            bool pointer = target.contains("extensions") && target["extensions"].contains("KHR_animation_pointer");
            std::string path = target["path"].get<std::string>();
            if (pointer) continue;  // not animated by this loader; validated in the extension checker
            if (path != "translation" && path != "rotation" && path != "scale" && path != "weights")
                raise(cp + "/target/path", "invalid value '" + path + "'");
            if (!target.contains("node")) continue;
            size_t node = target["node"].get<size_t>();
            if (!targets.insert({node, path}).second) raise(cp + "/target", "another channel has the same target");
            const Json& n = root["nodes"][node];
            if (path != "weights" && n.contains("matrix"))
                raise(cp + "/target", "channel cannot target TRS properties of a node with a matrix");
            size_t morphs = morphTargetCount(n);
            if (path == "weights" && morphs == 0) raise(cp + "/target", "channel targets weights of a node without morph targets");
            const Json& sampler = animation["samplers"][channel["sampler"].get<size_t>()];
            std::string sp = cp + "/sampler";
            const Json& input = root["accessors"][sampler["input"].get<size_t>()];
            const Json& output = root["accessors"][sampler["output"].get<size_t>()];
            if (input["type"] != "SCALAR" || input["componentType"] != kFloat)
                raise(sp, "sampler input must be {SCALAR, FLOAT}");
            if (!input.contains("min") || !input.contains("max")) raise(sp, "sampler input must define min and max");
            int64_t ct = output["componentType"].get<int64_t>();
            bool norm = output.value("normalized", false);
            std::string type = output["type"].get<std::string>();
            bool ok = path == "rotation" ? type == "VEC4" && (ct == kFloat || (norm && ct != kUnsignedInt))
                    : path == "weights"  ? type == "SCALAR" && (ct == kFloat || (norm && ct != kUnsignedInt))
                                         : type == "VEC3" && ct == kFloat;
            if (!ok) raise(sp, "invalid output format " + formatName(ct, type) + " for path '" + path + "'");
            bool cubic = sampler.value("interpolation", std::string("LINEAR")) == "CUBICSPLINE";
            uint64_t keys = input["count"].get<uint64_t>();
            if (cubic && keys < 2) raise(sp, "CUBICSPLINE needs at least 2 keys");
            uint64_t expected = keys * (cubic ? 3 : 1) * (path == "weights" ? morphs : 1);
            if (output["count"].get<uint64_t>() != expected)
                raise(sp, "output accessor count " + output["count"].dump() + ", expected " + std::to_string(expected));
            mLayout.useAccessor(sampler["input"].get<size_t>(), sp, ViewUse::Other);
            mLayout.useAccessor(sampler["output"].get<size_t>(), sp, ViewUse::Other);
        }
    }
}

void GltfGraphValidator::checkImages() {
    const Json& root = mJson.root();
    bool webp = false;
    if (root.contains("extensionsUsed"))
        for (const Json& e : root["extensionsUsed"]) webp = webp || e == "EXT_texture_webp";
    auto mimeOf = [&](const Json& image) -> std::string {
        if (image.contains("mimeType")) return image["mimeType"].get<std::string>();
        std::string uri = image.value("uri", std::string());
        if (uri.rfind("data:", 0) == 0) return uri.substr(5, uri.find_first_of(";,") - 5);
        auto ends = [&](const char* s) {
            std::string e(s);
            return uri.size() >= e.size() && uri.compare(uri.size() - e.size(), e.size(), e) == 0;
        };
        if (ends(".png")) return "image/png";
        if (ends(".jpg") || ends(".jpeg")) return "image/jpeg";
        if (ends(".webp")) return "image/webp";
        if (ends(".ktx2")) return "image/ktx2";
        return "";
    };
    for (size_t i = 0; i < mJson.count("images"); ++i) {
        const Json& image = root["images"][i];
        std::string ptr = childPointer("/images", i), mime = mimeOf(image);
        mJson.optEnum(image, ptr, "mimeType", {"image/png", "image/jpeg", "image/webp", "image/ktx2"});
        if (mime == "image/webp" && !webp) raise(ptr, "'image/webp' requires the EXT_texture_webp extension");
        if (image.contains("bufferView")) mLayout.useView(image["bufferView"].get<size_t>(), ptr + "/bufferView", ViewUse::Other);
    }
    for (size_t t = 0; t < mJson.count("textures"); ++t) {
        const Json& texture = root["textures"][t];
        std::string ptr = childPointer("/textures", t);
        if (texture.contains("source")) {
            std::string mime = mimeOf(root["images"][texture["source"].get<size_t>()]);
            if (mime != "image/png" && mime != "image/jpeg" && !mime.empty())
                raise(ptr + "/source", "texture source must be a PNG or JPEG image, not '" + mime + "'");
        }
        if (texture.contains("extensions") && texture["extensions"].contains("EXT_texture_webp")) {
            size_t source = texture["extensions"]["EXT_texture_webp"]["source"].get<size_t>();
            if (mimeOf(root["images"][source]) != "image/webp")
                raise(ptr + "/extensions/EXT_texture_webp/source", "EXT_texture_webp source must be a WebP image");
        }
    }
}

} // namespace tessera::assets
