#pragma once
/// @file GlbBuilder.h
/// Assembles a glTF 2.0 binary: the JSON document and one BIN chunk.

#include <nlohmann/json.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace tessera::creature {

/// glTF accessor component types (the GL enums the spec uses).
enum class GlbComponent : int {
    U8 = 5121,
    U16 = 5123,
    U32 = 5125,
    F32 = 5126,
};

/// glTF bufferView targets.
enum class GlbTarget : int {
    None = 0,
    ArrayBuffer = 34962,
    ElementArrayBuffer = 34963,
};

/// Collects buffer views and accessors over one binary buffer and writes the
/// .glb container (12-byte header, JSON chunk padded with spaces, BIN chunk
/// padded with zeros, both to 4 bytes). Every buffer view starts on a 4-byte
/// boundary, so any accessor component type is aligned and vertex
/// attributes meet glTF's 4-byte element rule without a byteStride. Object
/// keys are sorted (nlohmann::json), so the same calls give the same bytes.
class GlbBuilder {
public:
    GlbBuilder();

    /// The glTF document; buffers, bufferViews and accessors are filled in
    /// by this class, everything else by the caller.
    nlohmann::json& json() { return mJson; }

    /// Appends `bytes` as a new buffer view and returns its index.
    uint32_t addBufferView(std::span<const std::byte> bytes, GlbTarget target = GlbTarget::None);

    /// Appends a tightly packed typed array as a buffer view plus an accessor
    /// over it; returns the accessor index. `type` is "SCALAR", "VEC2", ...
    /// `min`/`max` are written when given (POSITION, animation inputs).
    template <class T>
    uint32_t addAccessor(const std::vector<T>& elements, GlbComponent component, const char* type,
                         size_t count, GlbTarget target, const std::optional<nlohmann::json>& min = {},
                         const std::optional<nlohmann::json>& max = {}) {
        uint32_t view = addBufferView(std::as_bytes(std::span(elements)), target);
        return addAccessorOver(view, component, type, count, min, max);
    }

    /// An accessor over an existing buffer view (or none, with view = -1, as
    /// KHR_draco_mesh_compression requires); returns its index.
    uint32_t addAccessorOver(int64_t view, GlbComponent component, const char* type, size_t count,
                             const std::optional<nlohmann::json>& min = {},
                             const std::optional<nlohmann::json>& max = {});

    /// The finished .glb file.
    std::vector<uint8_t> finish();

private:
    nlohmann::json mJson;
    std::vector<uint8_t> mBin;
};

} // namespace tessera::creature
