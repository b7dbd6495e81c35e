// The .impostor byte layout (ImpostorFile.h has the table). Every field is
// checked before the images are touched and the total size before any copy,
// so truncated or corrupted input ends in an error naming the file, never in
// a read past the buffer.
#include "tessera/character/ImpostorFile.h"

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

uint64_t fnv1a(std::span<const uint8_t> bytes) {
    uint64_t h = 0xCBF29CE484222325ull;
    for (uint8_t b : bytes) {
        h ^= b;
        h *= 0x100000001B3ull;
    }
    return h;
}

template <class T> void put(std::vector<uint8_t>& out, T value) {
    uint8_t raw[sizeof(T)];
    std::memcpy(raw, &value, sizeof(T));
    // Little-endian on disk whatever the host (every target Tessera builds
    // for is little-endian; this keeps the layout explicit).
    if constexpr (std::endian::native == std::endian::big) std::reverse(raw, raw + sizeof(T));
    const size_t at = out.size();
    out.resize(at + sizeof(T));
    std::memcpy(out.data() + at, raw, sizeof(T));
}

template <class T> T get(std::span<const uint8_t> bytes, size_t offset) {
    uint8_t raw[sizeof(T)];
    std::memcpy(raw, bytes.data() + offset, sizeof(T));
    if constexpr (std::endian::native == std::endian::big) std::reverse(raw, raw + sizeof(T));
    T value;
    std::memcpy(&value, raw, sizeof(T));
    return value;
}

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
    put(out, kImpostorFileVersion);
    for (const Constant& c : kConstants) put(out, c.value);
    put(out, atlas.size);
    put(out, atlas.layers);
    put(out, atlas.centreY);
    put(out, atlas.radius);
    assert(out.size() == kHeaderBytes);
    for (uint32_t m = 0; m < TS_IMPOSTOR_MIPS; ++m) {
        assert(atlas.albedo[m].size() == atlas.layerBytes(m) * atlas.layers);
        assert(atlas.normal[m].size() == atlas.layerBytes(m) * atlas.layers);
        out.insert(out.end(), atlas.albedo[m].begin(), atlas.albedo[m].end());
        out.insert(out.end(), atlas.normal[m].begin(), atlas.normal[m].end());
    }
    put(out, fnv1a(out));
    return out;
}

Result<ImpostorAtlas> decodeImpostorAtlas(std::span<const uint8_t> bytes, const std::string& name) {
    if (bytes.size() < sizeof(kMagic) && std::memcmp(bytes.data(), kMagic, bytes.size()) == 0)
        return fail(name, ": truncated: ", std::to_string(bytes.size()), " bytes");
    if (bytes.size() < sizeof(kMagic) || std::memcmp(bytes.data(), kMagic, sizeof(kMagic)) != 0)
        return fail(name, ": not a Tessera impostor file (no TSIMPOST magic)");
    if (bytes.size() < kHeaderBytes + kChecksumBytes)
        return fail(name, ": truncated: ", std::to_string(bytes.size()), " bytes, the header alone takes ",
                    std::to_string(kHeaderBytes + kChecksumBytes));
    const uint32_t version = get<uint32_t>(bytes, 8);
    if (version != kImpostorFileVersion)
        return fail(name, ": version ", std::to_string(version), ", this build reads version ",
                    std::to_string(kImpostorFileVersion), " (bake it again)");
    for (size_t i = 0; i < std::size(kConstants); ++i) {
        const uint32_t value = get<uint32_t>(bytes, 12 + 4 * i);
        if (value != kConstants[i].value)
            return fail(name, ": baked with ", kConstants[i].name, " ", std::to_string(value), ", this build draws ",
                        std::to_string(kConstants[i].value), " (bake it again)");
    }
    ImpostorAtlas atlas;
    atlas.size = get<uint32_t>(bytes, 32);
    atlas.layers = get<uint32_t>(bytes, 36);
    atlas.centreY = get<float>(bytes, 40);
    atlas.radius = get<float>(bytes, 44);
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
    if (bytes.size() < expected)
        return fail(name, ": truncated: ", std::to_string(bytes.size()), " bytes, its ", std::to_string(atlas.layers),
                    " layers need ", std::to_string(expected));
    if (bytes.size() > expected)
        return fail(name, ": ", std::to_string(bytes.size() - expected), " bytes after the end of its ",
                    std::to_string(atlas.layers), " layers");
    const size_t payload = size_t(expected - kChecksumBytes);
    if (get<uint64_t>(bytes, payload) != fnv1a(bytes.first(payload)))
        return fail(name, ": checksum mismatch (the file is corrupted)");
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
    const std::vector<uint8_t> bytes = encodeImpostorAtlas(atlas);
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    // Flushed before the check: a full disk shows only when the buffer goes out.
    if (!out || !out.flush()) return fail(file.string(), ": cannot write the impostor file");
    return {};
}

Result<ImpostorAtlas> readImpostorFile(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary | std::ios::ate);
    if (!in) return fail(file.string(), ": cannot open the impostor file");
    // One read of the whole file (megabytes): its size first.
    const std::streamoff size = in.tellg();
    if (size < 0) return fail(file.string(), ": cannot read the impostor file");
    std::vector<uint8_t> bytes(static_cast<size_t>(size));
    in.seekg(0);
    if (!in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(bytes.size())))
        return fail(file.string(), ": cannot read the impostor file");
    return decodeImpostorAtlas(bytes, file.string());
}

} // namespace tessera::character
