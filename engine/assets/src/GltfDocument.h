#pragma once
// GltfDocument: one glTF file read, checked and parsed. load() reads the
// bytes (bounded by the file size), splits GLB containers, parses the JSON,
// runs every structural validator, then lets tinygltf build the model
// (DracoDecoder decodes Draco) and runs the data checks on it. Throws GltfError.

#include "GltfTinyGltf.h"

#include <filesystem>

namespace tessera::assets {

class GltfDocument {
public:
    /// Reads and validates `file`; throws GltfError with a message naming the problem (not the file).
    static GltfDocument load(const std::filesystem::path& file);

    const tinygltf::Model& model() const { return mModel; }
    /// The raw JSON, for what tinygltf does not keep (extras).
    const nlohmann::json& json() const { return mJson; }

private:
    tinygltf::Model mModel;
    nlohmann::json mJson;
};

} // namespace tessera::assets
