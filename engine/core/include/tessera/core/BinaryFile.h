#pragma once
/// @file BinaryFile.h
/// What Tessera's own binary files share (.cctiles, .impostor): little-endian
/// fields, an FNV-1a checksum of everything before it at the end, and a
/// header that starts with an 8-byte magic and a uint32 version. Readers
/// check every size before they read, so bad input ends in an error naming
/// the file, never in a read past the buffer.

#include "tessera/core/Result.h"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace tessera::core {

/// 64-bit FNV-1a of `bytes`.
inline uint64_t fnv1a(std::span<const uint8_t> bytes) {
    uint64_t h = 0xCBF29CE484222325ull;
    for (uint8_t b : bytes) {
        h ^= b;
        h *= 0x100000001B3ull;
    }
    return h;
}

/// Appends `value` little-endian.
template <class T> void putLittle(std::vector<uint8_t>& out, T value) {
    uint8_t raw[sizeof(T)];
    std::memcpy(raw, &value, sizeof(T));
    if constexpr (std::endian::native == std::endian::big) std::reverse(raw, raw + sizeof(T));
    // resize + memcpy, not insert: GCC 12 warns falsely (-Warray-bounds)
    // about a small range insert once inlined.
    const size_t at = out.size();
    out.resize(at + sizeof(T));
    std::memcpy(out.data() + at, raw, sizeof(T));
}

/// The little-endian T at `offset` (the caller checked the size).
template <class T> T getLittle(std::span<const uint8_t> bytes, size_t offset) {
    uint8_t raw[sizeof(T)];
    std::memcpy(raw, bytes.data() + offset, sizeof(T));
    if constexpr (std::endian::native == std::endian::big) std::reverse(raw, raw + sizeof(T));
    T value;
    std::memcpy(&value, raw, sizeof(T));
    return value;
}

/// What a file format's header check needs: its magic, its kind in words
/// ("tile file"), the header's and checksum's bytes, its version and what
/// to do about another version ("regenerate it").
struct BinaryFormat {
    const char* magic = nullptr; ///< 8 characters, no terminator needed
    const char* kind = nullptr;
    size_t headerBytes = 0;
    size_t checksumBytes = 8;
    uint32_t version = 0;
    const char* remedy = nullptr;
};

/// Checks the magic, that the header and checksum fit, and the version
/// (a uint32 after the magic); fails naming `name`.
Status checkBinaryHeader(std::span<const uint8_t> bytes, const BinaryFormat& format, const std::string& name);
/// Checks that `bytes` is exactly `expected` long (`what`: "its 12 tiles")
/// and that its last 8 bytes are the FNV-1a of the rest.
Status checkBinarySizeAndChecksum(std::span<const uint8_t> bytes, uint64_t expected, const std::string& what,
                                  const std::string& name);
/// The whole file; fails naming it (`kind`: "tile file"; `hint` follows the
/// message when it cannot be opened).
Result<std::vector<uint8_t>> readBinaryFile(const std::filesystem::path& file, const char* kind,
                                            const char* hint = "");
/// Writes `bytes` to `file`, flushed: a full disk is an error.
Status writeBinaryFile(const std::filesystem::path& file, std::span<const uint8_t> bytes, const char* kind);

} // namespace tessera::core
