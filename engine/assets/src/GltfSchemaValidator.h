#pragma once
// GltfSchemaValidator: the glTF 2.0 JSON schema, by hand: types, required
// properties, ranges, enums, non-empty arrays and every index reference of
// the core objects. Extensions are delegated to GltfExtensionValidator.

#include "GltfExtensionValidator.h"
#include "JsonChecker.h"

namespace tessera::assets {

class GltfSchemaValidator {
public:
    explicit GltfSchemaValidator(const JsonChecker& json) : mJson(json), mExtensions(json) {}

    /// Throws GltfError at the first violation.
    void validate() const;

private:
    void checkCommon(const Json& o, const std::string& ptr, ExtensionLocation location) const;
    void checkAsset(const Json& asset) const;
    void checkBuffer(const Json& o, const std::string& ptr) const;
    void checkBufferView(const Json& o, const std::string& ptr) const;
    void checkAccessor(const Json& o, const std::string& ptr) const;
    void checkMesh(const Json& o, const std::string& ptr) const;
    void checkNode(const Json& o, const std::string& ptr) const;
    void checkSkin(const Json& o, const std::string& ptr) const;
    void checkAnimation(const Json& o, const std::string& ptr) const;
    void checkCamera(const Json& o, const std::string& ptr) const;
    void checkImage(const Json& o, const std::string& ptr) const;
    void checkTexture(const Json& o, const std::string& ptr) const;
    void checkSampler(const Json& o, const std::string& ptr) const;
    void checkMaterial(const Json& o, const std::string& ptr) const;
    void checkScene(const Json& o, const std::string& ptr) const;

    const JsonChecker& mJson;
    GltfExtensionValidator mExtensions;
};

} // namespace tessera::assets
