#pragma once
// GltfExtensionValidator: the `extensions` objects. Every extension used must
// be declared in extensionsUsed; known extensions must sit where their
// specification puts them and their content is checked (ranges, references);
// unknown ones are accepted as long as nothing requires them.

#include "JsonChecker.h"

namespace tessera::assets {

/// Where an extensions object sits (what glTF object owns it).
enum class ExtensionLocation {
    Root, Asset, Accessor, Animation, AnimationChannel, AnimationTarget, AnimationSampler, Buffer, BufferView,
    Camera, Image, Material, Mesh, Primitive, Node, Sampler, Scene, Skin, Texture, TextureInfo, Other
};

class GltfExtensionValidator {
public:
    explicit GltfExtensionValidator(const JsonChecker& json) : mJson(json) {}

    /// Checks o["extensions"] (if any) of an object at `ptr` of kind `location`.
    void check(const Json& o, const std::string& ptr, ExtensionLocation location) const;
    /// Checks a textureInfo object (index, texCoord, its extensions).
    void checkTextureInfo(const Json& o, const std::string& ptr) const;
    /// The root-level rules: extensionsUsed / extensionsRequired.
    void checkDeclarations() const;

private:
    void checkContent(const std::string& name, const Json& ext, const std::string& ptr, const Json& owner,
                      ExtensionLocation location) const;
    void checkLod(const Json& ext, const std::string& ptr, const Json& owner, ExtensionLocation location) const;
    void checkLights(const Json& ext, const std::string& ptr) const;
    void checkVariantsRoot(const Json& ext, const std::string& ptr) const;
    void checkVariantsPrimitive(const Json& ext, const std::string& ptr) const;
    void checkMaterialExtension(const std::string& name, const Json& ext, const std::string& ptr) const;

    const JsonChecker& mJson;
};

/// Extensions whose presence in extensionsRequired this loader honours.
bool isSupportedRequiredExtension(const std::string& name);

} // namespace tessera::assets
