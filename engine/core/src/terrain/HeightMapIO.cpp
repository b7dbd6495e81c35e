#include "tessera/terrain/HeightMapIO.h"

#include "tessera/core/ImageFile.h"

#include <cstring>
#include <fstream>
#include <memory>
#include <string>

#include <stb_image.h>

namespace tessera::terrain {
namespace {

constexpr unsigned char kPngSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

struct StbFree {
    void operator()(void* pixels) const { stbi_image_free(pixels); }
};

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

    const int length = int(data.size());
    int w = 0, h = 0, channels = 0;
    // Validate the header before decoding so a colour or oversized image is
    // rejected without allocating its pixels.
    if (!stbi_info_from_memory(data.data(), length, &w, &h, &channels))
        return fail(name, ": corrupt PNG (", stbi_failure_reason(), ")");
    if (channels != 1 && channels != 2)
        return fail(name, ": expected a grayscale PNG, got ", std::to_string(channels), " channels");
    const std::string dims = std::to_string(w) + "x" + std::to_string(h);
    if (w < int(kMinHeightMapSide) || h < int(kMinHeightMapSide))
        return fail(name, ": height map is ", dims, ", smaller than the minimum 2x2");
    if (w > int(kMaxHeightMapSide) || h > int(kMaxHeightMapSide))
        return fail(name, ": height map is ", dims, ", larger than the maximum 16384 per side");

    const size_t count = size_t(w) * size_t(h);
    std::vector<uint16_t> samples(count);
    int dw = 0, dh = 0, fileChannels = 0;
    // desired_channels = 1 makes stb drop the alpha of gray+alpha images.
    if (stbi_is_16_bit_from_memory(data.data(), length)) {
        std::unique_ptr<stbi_us, StbFree> pixels(
            stbi_load_16_from_memory(data.data(), length, &dw, &dh, &fileChannels, 1));
        if (!pixels) return fail(name, ": corrupt PNG (", stbi_failure_reason(), ")");
        std::memcpy(samples.data(), pixels.get(), count * sizeof(uint16_t));
    } else {
        std::unique_ptr<stbi_uc, StbFree> pixels(
            stbi_load_from_memory(data.data(), length, &dw, &dh, &fileChannels, 1));
        if (!pixels) return fail(name, ": corrupt PNG (", stbi_failure_reason(), ")");
        // v * 257 maps 0..255 onto 0..65535 exactly (0xAB -> 0xABAB).
        for (size_t k = 0; k < count; ++k) samples[k] = uint16_t(pixels.get()[k] * 257u);
    }
    return HeightField(uint32_t(w), uint32_t(h), std::move(samples), scale);
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
