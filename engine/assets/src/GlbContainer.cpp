#include "GlbContainer.h"

#include "GltfError.h"

#include <cstring>

namespace tessera::assets {

namespace {

constexpr uint32_t kMagic = 0x46546C67;      // "glTF"
constexpr uint32_t kChunkJson = 0x4E4F534A;  // "JSON"
constexpr uint32_t kChunkBin = 0x004E4942;   // "BIN\0"

uint32_t readU32(const std::vector<uint8_t>& bytes, size_t offset) {
    uint32_t v = 0;
    std::memcpy(&v, bytes.data() + offset, 4);
    return v;  // GLB is little-endian, as every platform Tessera targets
}

std::string hex(uint32_t v) {
    char text[16];
    std::snprintf(text, sizeof text, "0x%08x", v);
    return text;
}

} // namespace

bool hasGlbMagic(const std::vector<uint8_t>& bytes) { return bytes.size() >= 4 && readU32(bytes, 0) == kMagic; }

std::vector<uint8_t> makeGlb(std::string json, std::optional<std::string_view> bin) {
    while (json.size() % 4 != 0) json += ' ';
    size_t binPadded = bin ? (bin->size() + 3) / 4 * 4 : 0;
    std::vector<uint8_t> out(12 + 8 + json.size() + (bin ? 8 + binPadded : 0), 0);
    auto put = [&](size_t at, uint32_t v) { std::memcpy(out.data() + at, &v, 4); };
    put(0, kMagic);
    put(4, 2);
    put(8, static_cast<uint32_t>(out.size()));
    put(12, static_cast<uint32_t>(json.size()));
    put(16, kChunkJson);
    std::memcpy(out.data() + 20, json.data(), json.size());
    if (bin) {
        size_t at = 20 + json.size();
        put(at, static_cast<uint32_t>(binPadded));
        put(at + 4, kChunkBin);
        if (!bin->empty()) std::memcpy(out.data() + at + 8, bin->data(), bin->size());
    }
    return out;
}

GlbChunks parseGlb(const std::vector<uint8_t>& bytes) {
    if (bytes.size() < 12) raise("", "GLB: unexpected end of header");
    if (readU32(bytes, 0) != kMagic) raise("", "GLB: invalid magic " + hex(readU32(bytes, 0)));
    if (readU32(bytes, 4) != 2) raise("", "GLB: invalid version " + std::to_string(readU32(bytes, 4)));
    uint32_t length = readU32(bytes, 8);
    if (length <= 12) raise("", "GLB: declared length " + std::to_string(length) + " is too small");
    // Bytes after the declared length are ignored (the validator only warns about them).
    if (length > bytes.size())
        raise("", "GLB: declared length " + std::to_string(length) + " exceeds the file size " +
                      std::to_string(bytes.size()));
    GlbChunks chunks;
    bool haveJson = false;
    size_t offset = 12, index = 0;
    while (offset < length) {
        if (length - offset < 8) raise("", "GLB: unexpected end of chunk header");
        uint32_t chunkLength = readU32(bytes, offset), type = readU32(bytes, offset + 4);
        offset += 8;
        if (chunkLength % 4 != 0) raise("", "GLB: length of chunk " + hex(type) + " is not a multiple of 4");
        if (chunkLength > length - offset) raise("", "GLB: chunk " + hex(type) + " does not fit the file");
        std::string_view data(reinterpret_cast<const char*>(bytes.data() + offset), chunkLength);
        if (index == 0 && type != kChunkJson) raise("", "GLB: first chunk must be JSON, found " + hex(type));
        if (type == kChunkJson) {
            if (haveJson) raise("", "GLB: duplicate JSON chunk");
            if (chunkLength == 0) raise("", "GLB: JSON chunk cannot be empty");
            chunks.json = data;
            haveJson = true;
        } else if (type == kChunkBin) {
            if (chunks.bin) raise("", "GLB: duplicate BIN chunk");
            if (index != 1) raise("", "GLB: BIN chunk must be the second chunk");
            chunks.bin = data;
        }
        offset += chunkLength;
        ++index;
    }
    if (!haveJson) raise("", "GLB: no JSON chunk");
    return chunks;
}

} // namespace tessera::assets
