// The .cctiles byte layout (CageTiles.h has the table). Every read is
// bounds-checked before it happens, so truncated or corrupted input ends in
// an error naming the file, never in a read past the buffer.
#include "tessera/subdiv/CageTiles.h"

#include "tessera/core/BinaryFile.h"

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

using core::getLittle;
using core::putLittle;

constexpr core::BinaryFormat kFormat{kMagic, "tile file", kHeaderBytes, kChecksumBytes, kCageTilesVersion,
                                     "regenerate it"};

} // namespace

std::vector<uint8_t> encodeCageTiles(const CageTiles& tiles) {
    std::vector<uint8_t> out(kMagic, kMagic + sizeof(kMagic));
    putLittle(out, kCageTilesVersion);
    putLittle(out, tiles.cageVertices);
    putLittle(out, tiles.cageTriangles);
    putLittle(out, tiles.controlVertices);
    putLittle(out, tiles.topologyHash);
    putLittle(out, uint32_t(tiles.log2Sizes.size()));
    putLittle(out, tiles.scale);
    putLittle(out, tiles.bias);
    out.insert(out.end(), tiles.log2Sizes.begin(), tiles.log2Sizes.end());
    for (uint16_t q : tiles.quantized) putLittle(out, q);
    putLittle(out, core::fnv1a(out));
    return out;
}

Result<CageTiles> decodeCageTiles(std::span<const uint8_t> bytes, const std::string& name) {
    if (Status ok = core::checkBinaryHeader(bytes, kFormat, name); !ok) return ok.error();
    CageTiles tiles;
    tiles.cageVertices = getLittle<uint32_t>(bytes, 12);
    tiles.cageTriangles = getLittle<uint32_t>(bytes, 16);
    tiles.controlVertices = getLittle<uint32_t>(bytes, 20);
    tiles.topologyHash = getLittle<uint64_t>(bytes, 24);
    const uint32_t tileCount = getLittle<uint32_t>(bytes, 32);
    tiles.scale = getLittle<float>(bytes, 36);
    tiles.bias = getLittle<float>(bytes, 40);
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
    if (Status ok =
            core::checkBinarySizeAndChecksum(bytes, expected, "its " + std::to_string(tileCount) + " tiles", name);
        !ok)
        return ok.error();
    tiles.quantized.resize(size_t(coefficients));
    const size_t first = kHeaderBytes + tileCount;
    for (size_t i = 0; i < tiles.quantized.size(); ++i) tiles.quantized[i] = getLittle<uint16_t>(bytes, first + 2 * i);
    return tiles;
}

Status writeCageTiles(const std::filesystem::path& file, const CageTiles& tiles) {
    return core::writeBinaryFile(file, encodeCageTiles(tiles), "tile file");
}

Result<CageTiles> readCageTiles(const std::filesystem::path& file) {
    auto bytes = core::readBinaryFile(file, "tile file", " (the creature generator writes it beside the .glb)");
    if (!bytes) return bytes.error();
    return decodeCageTiles(bytes.value(), file.string());
}

} // namespace tessera::subdiv
