#include "TextureDecoder.h"

#include "GltfError.h"

#include "tessera/core/ImageFile.h"

#include <cstdint>

namespace tessera::assets {

namespace {

const tinygltf::Image& textureImage(const tinygltf::Model& model, int texture, const std::string& ptr) {
    if (texture < 0 || static_cast<size_t>(texture) >= model.textures.size()) raise(ptr, "unresolved texture");
    int source = model.textures[static_cast<size_t>(texture)].source;
    if (source < 0 || static_cast<size_t>(source) >= model.images.size())
        raise("/textures/" + std::to_string(texture), "texture has no image");
    const tinygltf::Image& image = model.images[static_cast<size_t>(source)];
    std::string name = image.uri.empty() || image.uri.rfind("data:", 0) == 0 ? "image " + std::to_string(source) : image.uri;
    if (image.image.empty()) raise("/images/" + std::to_string(source), "image '" + name + "' is missing");
    return image;
}

character::TextureImage decode(const tinygltf::Model& model, int texture, bool sixteenBit, const std::string& ptr) {
    const tinygltf::Image& image = textureImage(model, texture, ptr);
    const auto& bytes = image.image;
    if (bytes.size() > static_cast<size_t>(INT32_MAX)) raise(ptr, "image is too large");
    auto header = readImageHeader(bytes);
    if (!header || header->width == 0 || header->height == 0 ||
        uint64_t{header->width} * uint64_t{header->height} > (uint64_t{1} << 28))
        raise(ptr, "cannot decode image '" + image.uri.substr(0, 64) + "'");
    if (sixteenBit && !header->sixteenBit) raise(ptr, "displacement map must be a 16-bit PNG");
    // A displacement map's samples stay 16-bit (R16, the host's little-endian
    // order); colour and normal maps are RGBA8.
    auto pixels = decodeImage(bytes, sixteenBit ? PngLayout::Gray16 : PngLayout::Rgba8);
    if (!pixels)
        raise(ptr, std::string(sixteenBit ? "cannot decode displacement image: " : "cannot decode image: ") +
                       pixels.error().message);
    character::TextureImage out;
    out.width = pixels->width;
    out.height = pixels->height;
    out.format = sixteenBit ? character::TextureFormat::R16 : character::TextureFormat::Rgba8;
    out.bytes = std::move(pixels->bytes);
    return out;
}

} // namespace

void decodeMaterialTextures(const tinygltf::Model& model, const nlohmann::json& json, int material,
                            character::CharacterAsset& asset) {
    if (material < 0) return;
    const tinygltf::Material& m = model.materials[static_cast<size_t>(material)];
    std::string ptr = "/materials/" + std::to_string(material);
    if (m.pbrMetallicRoughness.baseColorTexture.index >= 0)
        asset.baseColor = decode(model, m.pbrMetallicRoughness.baseColorTexture.index, false,
                                 ptr + "/pbrMetallicRoughness/baseColorTexture");
    if (m.normalTexture.index >= 0) asset.normalMap = decode(model, m.normalTexture.index, false, ptr + "/normalTexture");
    const nlohmann::json& jm = json["materials"][static_cast<size_t>(material)];
    if (!jm.contains("extras") || !jm["extras"].is_object() || !jm["extras"].contains("tessera_displacement")) return;
    const nlohmann::json& d = jm["extras"]["tessera_displacement"];
    std::string dp = ptr + "/extras/tessera_displacement";
    if (!d.is_object() || !d.contains("texture") || !d["texture"].is_number_integer() || !d.contains("scale") ||
        !d["scale"].is_number() || !d.contains("bias") || !d["bias"].is_number())
        raise(dp, "needs integer 'texture' and numbers 'scale' and 'bias'");
    character::DisplacementMap map;
    map.image = decode(model, d["texture"].get<int>(), true, dp);
    map.scale = d["scale"].get<float>();
    map.bias = d["bias"].get<float>();
    asset.displacement = std::move(map);
}

} // namespace tessera::assets
