// The .impostor byte layout (ImpostorFile.h has the table). Every field is
// checked before the images are touched and the total size before any copy,
// so truncated or corrupted input ends in an error naming the file, never in
// a read past the buffer.
#include "tessera/character/ImpostorFile.h"

#include "tessera/core/BinaryFile.h"
#include "tessera/shaders/CrowdImpostor.h"

#include <algorithm>
#include <bit>
#include <cassert>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>

namespace tessera::character {
namespace {

constexpr char kMagic[8] = {'T', 'S', 'I', 'M', 'P', 'O', 'S', 'T'};
constexpr size_t kHeaderBytes = 48;
constexpr size_t kChecksumBytes = 8;

struct Constant {
    const char* name;
    uint32_t value;
};
constexpr Constant kConstants[] = {{"views", TS_IMPOSTOR_VIEWS},
                                   {"cell", TS_IMPOSTOR_CELL},
                                   {"phases", TS_IMPOSTOR_PHASES},
                                   {"mips", TS_IMPOSTOR_MIPS},
                                   {"border", TS_IMPOSTOR_BORDER}};

using core::getLittle;
using core::putLittle;

constexpr core::BinaryFormat kFormat{kMagic, "impostor file", kHeaderBytes, kChecksumBytes, kImpostorFileVersion,
                                     "bake it again"};

// Bytes of every layer of one image at each mip, for this build's layout.
uint64_t imageBytes(uint32_t layers, uint32_t mip) {
    const uint64_t side = uint64_t(TS_IMPOSTOR_VIEWS * TS_IMPOSTOR_CELL) >> mip;
    return side * side * 4u * layers;
}

} // namespace

std::vector<uint8_t> encodeImpostorAtlas(const ImpostorAtlas& atlas) {
    assert(atlas.albedo.size() == TS_IMPOSTOR_MIPS && atlas.normal.size() == TS_IMPOSTOR_MIPS);
    std::vector<uint8_t> out(kMagic, kMagic + sizeof(kMagic));
    out.reserve(size_t(atlas.bytes()) + kHeaderBytes + kChecksumBytes);
    putLittle(out, kImpostorFileVersion);
    for (const Constant& c : kConstants) putLittle(out, c.value);
    putLittle(out, atlas.size);
    putLittle(out, atlas.layers);
    putLittle(out, atlas.centreY);
    putLittle(out, atlas.radius);
    assert(out.size() == kHeaderBytes);
    for (uint32_t m = 0; m < TS_IMPOSTOR_MIPS; ++m) {
        assert(atlas.albedo[m].size() == atlas.layerBytes(m) * atlas.layers);
        assert(atlas.normal[m].size() == atlas.layerBytes(m) * atlas.layers);
        out.insert(out.end(), atlas.albedo[m].begin(), atlas.albedo[m].end());
        out.insert(out.end(), atlas.normal[m].begin(), atlas.normal[m].end());
    }
    putLittle(out, core::fnv1a(out));
    return out;
}

Result<ImpostorAtlas> decodeImpostorAtlas(std::span<const uint8_t> bytes, const std::string& name) {
    if (Status ok = core::checkBinaryHeader(bytes, kFormat, name); !ok) return ok.error();
    for (size_t i = 0; i < std::size(kConstants); ++i) {
        const uint32_t value = getLittle<uint32_t>(bytes, 12 + 4 * i);
        if (value != kConstants[i].value)
            return fail(name, ": baked with ", kConstants[i].name, " ", std::to_string(value), ", this build draws ",
                        std::to_string(kConstants[i].value), " (bake it again)");
    }
    ImpostorAtlas atlas;
    atlas.size = getLittle<uint32_t>(bytes, 32);
    atlas.layers = getLittle<uint32_t>(bytes, 36);
    atlas.centreY = getLittle<float>(bytes, 40);
    atlas.radius = getLittle<float>(bytes, 44);
    if (atlas.size != TS_IMPOSTOR_VIEWS * TS_IMPOSTOR_CELL)
        return fail(name, ": layers of ", std::to_string(atlas.size), " texels a side, the layout's are ",
                    std::to_string(TS_IMPOSTOR_VIEWS * TS_IMPOSTOR_CELL));
    if (atlas.layers == 0 || atlas.layers % TS_IMPOSTOR_PHASES != 0)
        return fail(name, ": ", std::to_string(atlas.layers), " layers, not a whole number of clips of ",
                    std::to_string(TS_IMPOSTOR_PHASES), " phases");
    if (!std::isfinite(atlas.centreY) || !std::isfinite(atlas.radius) || !(atlas.radius > 0.0f))
        return fail(name, ": bad sphere (centre height ", std::to_string(atlas.centreY), ", radius ",
                    std::to_string(atlas.radius), ")");
    uint64_t expected = kHeaderBytes + kChecksumBytes;
    for (uint32_t m = 0; m < TS_IMPOSTOR_MIPS; ++m) expected += 2 * imageBytes(atlas.layers, m);
    if (Status ok = core::checkBinarySizeAndChecksum(bytes, expected,
                                                     "its " + std::to_string(atlas.layers) + " layers", name);
        !ok)
        return ok.error();
    size_t at = kHeaderBytes;
    for (uint32_t m = 0; m < TS_IMPOSTOR_MIPS; ++m) {
        const size_t n = size_t(imageBytes(atlas.layers, m));
        atlas.albedo.emplace_back(bytes.begin() + at, bytes.begin() + at + n);
        at += n;
        atlas.normal.emplace_back(bytes.begin() + at, bytes.begin() + at + n);
        at += n;
    }
    return atlas;
}

Status writeImpostorFile(const std::filesystem::path& file, const ImpostorAtlas& atlas) {
    return core::writeBinaryFile(file, encodeImpostorAtlas(atlas), "impostor file");
}

Result<ImpostorAtlas> readImpostorFile(const std::filesystem::path& file) {
    auto bytes = core::readBinaryFile(file, "impostor file");
    if (!bytes) return bytes.error();
    return decodeImpostorAtlas(bytes.value(), file.string());
}

} // namespace tessera::character
