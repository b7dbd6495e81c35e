#pragma once
// GlbContainer: the binary glTF container (12-byte header, a JSON chunk, an
// optional BIN chunk), checked strictly before anything reads from it.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tessera::assets {

struct GlbChunks {
    std::string_view json;
    std::optional<std::string_view> bin;  ///< views into the file bytes
};

/// True when the bytes start with the GLB magic "glTF".
bool hasGlbMagic(const std::vector<uint8_t>& bytes);
/// Builds a GLB from a JSON text and an optional BIN chunk (padding both to 4 bytes).
std::vector<uint8_t> makeGlb(std::string json, std::optional<std::string_view> bin);
/// Splits a GLB file into its chunks; throws GltfError on any structural fault.
GlbChunks parseGlb(const std::vector<uint8_t>& bytes);

} // namespace tessera::assets
