#pragma once
// GltfMeshValidator: mesh primitives. Attribute names and formats (with
// KHR_mesh_quantization's wider set), equal counts, index formats, morph
// targets, and the material's needs (texture coordinate sets, tangent space).

#include "GltfLayoutValidator.h"

namespace tessera::assets {

class GltfMeshValidator {
public:
    GltfMeshValidator(const JsonChecker& json, GltfLayoutValidator& layout) : mJson(json), mLayout(layout) {}

    void validate();

private:
    void checkPrimitive(const Json& primitive, const std::string& ptr, bool quantized);
    void checkAttributeFormat(const std::string& semantic, const Json& accessor, const std::string& ptr,
                              bool quantized, bool morph) const;
    void checkMaterialNeeds(const Json& primitive, const std::string& ptr, size_t texcoordSets) const;

    const JsonChecker& mJson;
    GltfLayoutValidator& mLayout;
};

} // namespace tessera::assets
