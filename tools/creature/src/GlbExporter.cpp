#include "creature/GlbExporter.h"

#include "GlbAnimationWriter.h"
#include "GlbAssetCheck.h"
#include "GlbBuilder.h"
#include "GlbImageEncoder.h"
#include "GlbMeshWriter.h"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>

namespace tessera::creature {

namespace {

using nlohmann::json;

constexpr int kLinear = 9729;
// MSFT_lod's screen-coverage hint (extras.MSFT_screencoverage): the cage
// from full coverage down to 2%, the far mesh from 2% to 0 (never culled).
// A hint for other readers only; the crowd picks its tiers itself.
constexpr double kFarScreenCoverage = 0.02;
constexpr int kClampToEdge = 33071;

json nodeJson(const character::SkeletonNode& node) {
    json out = json::object();
    if (!node.name.empty()) out["name"] = node.name;
    const character::NodeTransform& t = node.rest;
    // Identity parts are glTF's defaults; leaving them out keeps files small.
    if (t.translation != glm::vec3(0.0f)) out["translation"] = {t.translation.x, t.translation.y, t.translation.z};
    if (t.rotation != glm::quat(1.0f, 0.0f, 0.0f, 0.0f)) {
        out["rotation"] = {t.rotation.x, t.rotation.y, t.rotation.z, t.rotation.w};
    }
    if (t.scale != glm::vec3(1.0f)) out["scale"] = {t.scale.x, t.scale.y, t.scale.z};
    return out;
}

// The deepest node that is an ancestor of (or equal to) every joint, or -1.
int32_t commonRoot(const character::Skeleton& skeleton, const std::vector<character::SkinBinding>& bindings) {
    std::vector<int32_t> chain;  // the first joint and its ancestors, deepest first
    for (int32_t n = static_cast<int32_t>(bindings.front().node); n >= 0; n = skeleton.nodes[n].parent) chain.push_back(n);
    size_t best = 0;  // chain[best..] are common to every joint seen so far
    for (const character::SkinBinding& binding : bindings) {
        size_t found = chain.size();
        for (int32_t n = static_cast<int32_t>(binding.node); n >= 0 && found == chain.size(); n = skeleton.nodes[n].parent) {
            for (size_t i = best; i < chain.size(); ++i) {
                if (chain[i] == n) {
                    found = i;
                    break;
                }
            }
        }
        if (found == chain.size()) return -1;
        best = std::max(best, found);
    }
    return chain[best];
}

// glTF validators demand an exactly affine last row; generated inverses of
// affine matrices can carry rounding noise there.
glm::mat4 affine(glm::mat4 m) {
    m[0][3] = m[1][3] = m[2][3] = 0.0f;
    m[3][3] = 1.0f;
    return m;
}

void writeNodesAndSkin(GlbBuilder& glb, const character::CharacterAsset& asset, bool skinned) {
    json& doc = glb.json();
    const auto& nodes = asset.skeleton.nodes;
    json out = json::array();
    std::vector<json> children(nodes.size(), json::array());
    json roots = json::array();
    for (size_t i = 0; i < nodes.size(); ++i) {
        out.push_back(nodeJson(nodes[i]));
        if (nodes[i].parent < 0) roots.push_back(i);
        else children[nodes[i].parent].push_back(i);
    }
    for (size_t i = 0; i < nodes.size(); ++i) {
        if (!children[i].empty()) out[i]["children"] = children[i];
    }
    // The mesh node is a root without a transform, as glTF wants for
    // skinned meshes (the skin's joints place the vertices).
    json meshNode = {{"name", asset.name.empty() ? "cage" : asset.name}, {"mesh", 0}};
    if (skinned) meshNode["skin"] = 0;
    roots.push_back(out.size());
    // The far mesh is an MSFT_lod level: a node outside the scene (readers
    // without the extension see only the cage) with mesh 1 and the same skin.
    const size_t farNode = out.size() + 1;
    if (asset.farMesh) {
        meshNode["extensions"] = {{"MSFT_lod", {{"ids", json::array({farNode})}}}};
        meshNode["extras"] = {{"MSFT_screencoverage", json::array({kFarScreenCoverage, 0.0})}};
    }
    out.push_back(std::move(meshNode));
    if (asset.farMesh) {
        json far = {{"name", (asset.name.empty() ? std::string("cage") : asset.name) + "_far"}, {"mesh", 1}};
        if (skinned) far["skin"] = 0;
        out.push_back(std::move(far));
    }
    doc["nodes"] = std::move(out);
    doc["scenes"] = json::array({{{"nodes", roots}}});
    doc["scene"] = 0;
    if (!skinned) return;

    std::vector<float> matrices;
    json joints = json::array();
    for (const character::SkinBinding& binding : asset.cage.bindings) {
        joints.push_back(binding.node);
        glm::mat4 m = affine(binding.inverseBind);
        for (int c = 0; c < 4; ++c) {
            for (int r = 0; r < 4; ++r) matrices.push_back(m[c][r]);  // column-major, as glTF
        }
    }
    json skin = {{"joints", joints},
                 {"inverseBindMatrices", glb.addAccessor(matrices, GlbComponent::F32, "MAT4", joints.size(),
                                                         GlbTarget::None)}};
    if (int32_t root = commonRoot(asset.skeleton, asset.cage.bindings); root >= 0) skin["skeleton"] = root;
    doc["skins"] = json::array({skin});
}

Status writeMaterial(GlbBuilder& glb, const character::CharacterAsset& asset, const std::string& file) {
    json& doc = glb.json();
    json images = json::array();
    json textures = json::array();
    // Adds `image` as an embedded PNG and a texture; returns the texture index.
    auto addTexture = [&](const character::TextureImage& image, const char* what) -> Result<size_t> {
        Result<std::vector<uint8_t>> png = encodePng(image, (file + ": " + what).c_str());
        if (!png) return png.error();
        uint32_t view = glb.addBufferView(std::as_bytes(std::span(png.value())));
        images.push_back({{"bufferView", view}, {"mimeType", "image/png"}});
        textures.push_back({{"sampler", 0}, {"source", images.size() - 1}});
        return textures.size() - 1;
    };

    json material = {{"name", asset.name.empty() ? "skin" : asset.name + "_skin"}};
    // Creature skin is a dielectric; glTF's default metallic factor is 1.
    json pbr = {{"metallicFactor", 0.0}, {"roughnessFactor", 0.8}};
    if (asset.baseColor) {
        Result<size_t> texture = addTexture(*asset.baseColor, "base colour map");
        if (!texture) return texture.error();
        pbr["baseColorTexture"] = {{"index", texture.value()}};
    }
    material["pbrMetallicRoughness"] = pbr;
    if (asset.normalMap) {
        Result<size_t> texture = addTexture(*asset.normalMap, "normal map");
        if (!texture) return texture.error();
        material["normalTexture"] = {{"index", texture.value()}};
    }
    if (asset.displacement) {
        Result<size_t> texture = addTexture(asset.displacement->image, "displacement map");
        if (!texture) return texture.error();
        // docs: /work/briefs/extras.md, docs/CHARACTERS.md. Floats become
        // doubles, which nlohmann prints with round-trip precision.
        material["extras"] = {{"tessera_displacement",
                               {{"texture", texture.value()},
                                {"scale", asset.displacement->scale},
                                {"bias", asset.displacement->bias}}}};
    }
    doc["materials"] = json::array({material});
    if (!images.empty()) {
        doc["images"] = images;
        doc["textures"] = textures;
        doc["samplers"] = json::array({{{"magFilter", kLinear},
                                        {"minFilter", kLinear},
                                        {"wrapS", kClampToEdge},
                                        {"wrapT", kClampToEdge}}});
    }
    return {};
}

Status writeFile(const std::vector<uint8_t>& bytes, const std::filesystem::path& file) {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    if (!out) return fail(file.string(), ": cannot open for writing (", std::strerror(errno), ")");
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    out.close();
    if (!out) return fail(file.string(), ": write failed (", std::strerror(errno), ")");
    return {};
}

} // namespace

Result<void> exportGlb(const character::CharacterAsset& asset, const std::filesystem::path& file,
                       const ExportOptions& options) {
    const std::string name = file.filename().string();
    if (Status s = checkCharacter(asset, name); !s) return s;
    const bool skinned = !asset.cage.bindings.empty();

    GlbBuilder glb;
    json& doc = glb.json();
    doc["asset"] = {{"generator", "Tessera creaturegen"}, {"version", "2.0"}};
    writeNodesAndSkin(glb, asset, skinned);

    Result<json> primitive = writePrimitive(glb, asset.cage, skinned, options, name);
    if (!primitive) return primitive.error();
    json mesh = {{"primitives", json::array({primitive.value()})}};
    if (!asset.name.empty()) mesh["name"] = asset.name;
    doc["meshes"] = json::array({mesh});
    json used = json::array();
    if (options.draco) {
        used.push_back("KHR_draco_mesh_compression");
        doc["extensionsRequired"] = json::array({"KHR_draco_mesh_compression"});
    }
    if (asset.farMesh) {
        // Uncompressed: a few hundred triangles are a few kilobytes, and the
        // loader gets exactly the vertices the simplification chose (Draco
        // would reorder and quantise them).
        ExportOptions plain = options;
        plain.draco = false;
        Result<json> farPrimitive = writePrimitive(glb, *asset.farMesh, skinned, plain, name);
        if (!farPrimitive) return farPrimitive.error();
        json far = {{"primitives", json::array({farPrimitive.value()})}};
        far["name"] = (asset.name.empty() ? std::string("cage") : asset.name) + "_far";
        doc["meshes"].push_back(std::move(far));
        used.push_back("MSFT_lod");  // optional: without it, a reader draws the cage
    }
    if (!used.empty()) doc["extensionsUsed"] = std::move(used);

    if (Status s = writeMaterial(glb, asset, name); !s) return s;
    if (json animations = writeAnimations(glb, asset.clips); !animations.empty()) doc["animations"] = animations;
    return writeFile(glb.finish(), file);
}

} // namespace tessera::creature
