#pragma once
// Sizes of glTF accessor component types and element types.

#include <cstdint>
#include <string>

namespace tessera::assets {

constexpr int kByte = 5120, kUnsignedByte = 5121, kShort = 5122, kUnsignedShort = 5123, kUnsignedInt = 5125,
              kFloat = 5126;

inline uint32_t componentSize(int64_t componentType) {
    switch (componentType) {
    case kByte: case kUnsignedByte: return 1;
    case kShort: case kUnsignedShort: return 2;
    default: return 4;
    }
}

inline uint32_t componentCount(const std::string& type) {
    if (type == "SCALAR") return 1;
    if (type == "VEC2") return 2;
    if (type == "VEC3") return 3;
    if (type == "VEC4" || type == "MAT2") return 4;
    if (type == "MAT3") return 9;
    return 16;
}

/// Bytes of one element, with the 4-byte column alignment matrices need.
inline uint32_t elementSize(int64_t componentType, const std::string& type) {
    uint32_t size = componentSize(componentType);
    if (type == "MAT2" && size == 1) return 8;
    if (type == "MAT3" && size == 1) return 12;
    if (type == "MAT3" && size == 2) return 24;
    return size * componentCount(type);
}

/// Bytes from an element's start to the end of its last component (a matrix's
/// last column is not padded).
inline uint32_t elementEnd(int64_t componentType, const std::string& type) {
    uint32_t n = type == "MAT2" ? 2 : type == "MAT3" ? 3 : type == "MAT4" ? 4 : 0;
    if (n == 0) return elementSize(componentType, type);
    uint32_t column = n * componentSize(componentType);
    return (n - 1) * ((column + 3) / 4 * 4) + column;
}

/// "{VEC3, FLOAT}" for messages.
inline std::string formatName(int64_t componentType, const std::string& type) {
    const char* names[] = {"BYTE", "UNSIGNED_BYTE", "SHORT", "UNSIGNED_SHORT", "?", "UNSIGNED_INT", "FLOAT"};
    int64_t i = componentType - kByte;
    return "{" + type + ", " + (i >= 0 && i <= 6 ? names[i] : "?") + "}";
}

} // namespace tessera::assets
