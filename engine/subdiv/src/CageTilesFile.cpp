// The .cctiles byte layout (CageTiles.h has the table). Every read is
// bounds-checked before it happens, so truncated or corrupted input ends in
// an error naming the file, never in a read past the buffer.
#include "tessera/subdiv/CageTiles.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>

namespace tessera::subdiv {

namespace {

constexpr char kMagic[8] = {'T', 'S', 'C', 'C', 'T', 'I', 'L', 'E'};
constexpr size_t kHeaderBytes = 44;
constexpr size_t kChecksumBytes = 8;

uint64_t fnv1a(std::span<const uint8_t> bytes) {
    uint64_t h = 0xCBF29CE484222325ull;
    for (uint8_t b : bytes) {
        h ^= b;
        h *= 0x100000001B3ull;
    }
    return h;
}

template <class T>
void put(std::vector<uint8_t>& out, T value) {
    uint8_t raw[sizeof(T)];
    std::memcpy(raw, &value, sizeof(T));
    // Little-endian on disk whatever the host (every target Tessera builds
    // for is little-endian; this keeps the layout explicit).
    if constexpr (std::endian::native == std::endian::big) std::reverse(raw, raw + sizeof(T));
    // resize + memcpy, not insert: GCC 12 warns falsely (-Warray-bounds)
    // about a small range insert once inlined.
    const size_t at = out.size();
    out.resize(at + sizeof(T));
    std::memcpy(out.data() + at, raw, sizeof(T));
}

template <class T>
T get(std::span<const uint8_t> bytes, size_t offset) {
    uint8_t raw[sizeof(T)];
    std::memcpy(raw, bytes.data() + offset, sizeof(T));
    if constexpr (std::endian::native == std::endian::big) std::reverse(raw, raw + sizeof(T));
    T value;
    std::memcpy(&value, raw, sizeof(T));
    return value;
}

} // namespace

std::vector<uint8_t> encodeCageTiles(const CageTiles& tiles) {
    std::vector<uint8_t> out(kMagic, kMagic + sizeof(kMagic));
    put(out, kCageTilesVersion);
    put(out, tiles.cageVertices);
    put(out, tiles.cageTriangles);
    put(out, tiles.controlVertices);
    put(out, tiles.topologyHash);
    put(out, uint32_t(tiles.log2Sizes.size()));
    put(out, tiles.scale);
    put(out, tiles.bias);
    out.insert(out.end(), tiles.log2Sizes.begin(), tiles.log2Sizes.end());
    for (uint16_t q : tiles.quantized) put(out, q);
    put(out, fnv1a(out));
    return out;
}

Result<CageTiles> decodeCageTiles(std::span<const uint8_t> bytes, const std::string& name) {
    if (bytes.size() < sizeof(kMagic) && std::memcmp(bytes.data(), kMagic, bytes.size()) == 0)
        return fail(name, ": truncated: ", std::to_string(bytes.size()), " bytes");
    if (bytes.size() < sizeof(kMagic) || std::memcmp(bytes.data(), kMagic, sizeof(kMagic)) != 0)
        return fail(name, ": not a Tessera tile file (no TSCCTILE magic)");
    if (bytes.size() < kHeaderBytes + kChecksumBytes)
        return fail(name, ": truncated: ", std::to_string(bytes.size()), " bytes, the header alone takes ",
                    std::to_string(kHeaderBytes + kChecksumBytes));
    const uint32_t version = get<uint32_t>(bytes, 8);
    if (version != kCageTilesVersion)
        return fail(name, ": version ", std::to_string(version), ", this build reads version ",
                    std::to_string(kCageTilesVersion), " (regenerate it)");
    CageTiles tiles;
    tiles.cageVertices = get<uint32_t>(bytes, 12);
    tiles.cageTriangles = get<uint32_t>(bytes, 16);
    tiles.controlVertices = get<uint32_t>(bytes, 20);
    tiles.topologyHash = get<uint64_t>(bytes, 24);
    const uint32_t tileCount = get<uint32_t>(bytes, 32);
    tiles.scale = get<float>(bytes, 36);
    tiles.bias = get<float>(bytes, 40);
    if (tileCount == 0) return fail(name, ": no tiles");
    if (!std::isfinite(tiles.scale) || tiles.scale < 0.0f || !std::isfinite(tiles.bias))
        return fail(name, ": bad coefficient range (scale ", std::to_string(tiles.scale), ", bias ",
                    std::to_string(tiles.bias), ")");
    if (bytes.size() < kHeaderBytes + uint64_t(tileCount) + kChecksumBytes)
        return fail(name, ": truncated: ", std::to_string(bytes.size()), " bytes, the header and ",
                    std::to_string(tileCount), " tile sizes take more");
    tiles.log2Sizes.assign(bytes.begin() + kHeaderBytes, bytes.begin() + kHeaderBytes + tileCount);
    for (uint32_t t = 0; t < tileCount; ++t)
        if (tiles.log2Sizes[t] < 1 || tiles.log2Sizes[t] > 12)
            return fail(name, ": tile ", std::to_string(t), " has log2 size ", std::to_string(tiles.log2Sizes[t]),
                        " (1 to 12)");
    const uint64_t coefficients = tiles.coefficientCount();
    const uint64_t expected = kHeaderBytes + uint64_t(tileCount) + 2 * coefficients + kChecksumBytes;
    if (bytes.size() < expected)
        return fail(name, ": truncated: ", std::to_string(bytes.size()), " bytes, its ", std::to_string(tileCount),
                    " tiles need ", std::to_string(expected));
    if (bytes.size() > expected)
        return fail(name, ": ", std::to_string(bytes.size() - expected), " bytes after the end of its ",
                    std::to_string(tileCount), " tiles");
    const size_t payload = size_t(expected - kChecksumBytes);
    if (get<uint64_t>(bytes, payload) != fnv1a(bytes.first(payload)))
        return fail(name, ": checksum mismatch (the file is corrupted)");
    tiles.quantized.resize(size_t(coefficients));
    const size_t first = kHeaderBytes + tileCount;
    for (size_t i = 0; i < tiles.quantized.size(); ++i) tiles.quantized[i] = get<uint16_t>(bytes, first + 2 * i);
    return tiles;
}

Status writeCageTiles(const std::filesystem::path& file, const CageTiles& tiles) {
    const std::vector<uint8_t> bytes = encodeCageTiles(tiles);
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    // Flushed before the check: a full disk shows only when the buffer goes out.
    if (!out || !out.flush()) return fail(file.string(), ": cannot write the tile file");
    return {};
}

Result<CageTiles> readCageTiles(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) return fail(file.string(), ": cannot open the tile file (the creature generator writes it beside the .glb)");
    std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) return fail(file.string(), ": cannot read the tile file");
    return decodeCageTiles(bytes, file.string());
}

} // namespace tessera::subdiv
