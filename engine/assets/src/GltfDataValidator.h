#pragma once
// GltfDataValidator: the values inside the buffers, once tinygltf has loaded
// them (and decoded Draco): finite floats, declared min/max, index ranges,
// unit normals/tangents/rotations, normalized weights, valid joints,
// increasing key times, affine inverse bind matrices, image signatures.

#include "AccessorReader.h"

#include <nlohmann/json.hpp>

namespace tessera::assets {

class GltfDataValidator {
public:
    GltfDataValidator(const tinygltf::Model& model, const nlohmann::json& json)
        : mModel(model), mJson(json), mReader(model) {}

    void validate() const;

private:
    void checkAccessorBounds() const;
    void checkPrimitives() const;
    void checkAnimations() const;
    void checkSkins() const;
    void checkImages() const;

    const tinygltf::Model& mModel;
    const nlohmann::json& mJson;
    AccessorReader mReader;
};

} // namespace tessera::assets
