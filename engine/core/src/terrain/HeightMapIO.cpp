#include "tessera/terrain/HeightMapIO.h"

#include "tessera/core/ImageFile.h"

#include <cstring>
#include <fstream>
#include <string>

namespace tessera::terrain {
namespace {

constexpr unsigned char kPngSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

Result<std::vector<unsigned char>> readFile(const std::filesystem::path& path) {
    const std::string name = path.string();
    std::error_code ec;
    auto status = std::filesystem::status(path, ec);
    if (!std::filesystem::exists(status)) return fail(name, ": file not found");
    if (!std::filesystem::is_regular_file(status)) return fail(name, ": not a regular file");

    std::ifstream in(path, std::ios::binary);
    if (!in) return fail(name, ": cannot open file for reading");
    std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)),
                                     std::istreambuf_iterator<char>());
    if (in.bad()) return fail(name, ": read error");
    return bytes;
}

} // namespace

Result<HeightField> loadHeightMapPng(const std::filesystem::path& path, TerrainScale scale) {
    const std::string name = path.string();
    auto bytes = readFile(path);
    if (!bytes) return bytes.error();
    const std::vector<unsigned char>& data = *bytes;

    // stb_image would happily decode a JPEG or BMP too; a height map must be a
    // lossless PNG, so check the signature ourselves and say so plainly.
    if (data.size() < sizeof(kPngSignature) ||
        std::memcmp(data.data(), kPngSignature, sizeof(kPngSignature)) != 0)
        return fail(name, ": not a PNG file");
    if (data.size() > size_t(INT32_MAX)) return fail(name, ": file too large");

    // Validate the header before decoding so a colour or oversized image is
    // rejected without allocating its pixels.
    auto header = readImageHeader(data);
    if (!header) return fail(name, ": corrupt PNG (", header.error().message, ")");
    const uint32_t w = header->width, h = header->height;
    if (header->channels != 1 && header->channels != 2)
        return fail(name, ": expected a grayscale PNG, got ", std::to_string(header->channels), " channels");
    const std::string dims = std::to_string(w) + "x" + std::to_string(h);
    if (w < kMinHeightMapSide || h < kMinHeightMapSide)
        return fail(name, ": height map is ", dims, ", smaller than the minimum 2x2");
    if (w > kMaxHeightMapSide || h > kMaxHeightMapSide)
        return fail(name, ": height map is ", dims, ", larger than the maximum 16384 per side");

    // Gray16 drops the alpha of gray+alpha images and widens 8-bit samples
    // by 257, mapping 0..255 onto 0..65535 exactly (0xAB -> 0xABAB).
    auto pixels = decodeImage(data, PngLayout::Gray16);
    if (!pixels) return fail(name, ": corrupt PNG (", pixels.error().message, ")");
    if (pixels->width != w || pixels->height != h) return fail(name, ": corrupt PNG (its header and pixels disagree)");
    std::vector<uint16_t> samples(size_t(w) * size_t(h));
    std::memcpy(samples.data(), pixels->bytes.data(), samples.size() * sizeof(uint16_t));
    return HeightField(w, h, std::move(samples), scale);
}

Status saveHeightMapPng16(const std::filesystem::path& path, uint32_t width, uint32_t height,
                          const std::vector<uint16_t>& samples) {
    const std::string name = path.string();
    if (width == 0 || height == 0 || width > kMaxHeightMapSide || height > kMaxHeightMapSide)
        return fail(name, ": cannot write a ", std::to_string(width), "x", std::to_string(height),
                    " height map (each side must be 1..16384)");
    if (samples.size() != size_t(width) * height)
        return fail(name, ": ", std::to_string(samples.size()), " samples given for a ",
                    std::to_string(width), "x", std::to_string(height), " height map");
    return writePng(path, PngPixels{width, height, PngLayout::Gray16, samples.data()});
}

} // namespace tessera::terrain
