#include "common/DetailTextureArray.h"

#include "common/MipImage.h"
#include "tessera/shaders/TerrainUniforms.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

namespace tessera::backends {

namespace {

const char* const kLayerNames[TS_DETAIL_LAYERS] = {"grass", "dirt", "rock", "snow"};

// Each material's average colour (sRGB bytes) for a terrain created without
// detail textures: the flat albedos the full look was tuned with.
const uint8_t kFlatColors[TS_DETAIL_LAYERS][4] = {
    {55, 81, 31, 255}, {80, 72, 50, 255}, {108, 103, 97, 255}, {231, 235, 241, 255}};

float toLinear(uint8_t v) {
    const float c = float(v) / 255.0f;
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

} // namespace

Result<DetailTextureArray> DetailTextureArray::create(gpu::Device& device, std::span<const Rgba8Image> layers) {
    std::vector<Rgba8Image> flat;
    if (layers.empty()) {
        for (const auto& color : kFlatColors) flat.push_back({1, 1, std::vector<uint8_t>(color, color + 4)});
        layers = flat;
    }
    if (layers.size() != TS_DETAIL_LAYERS)
        return fail("terrain detail textures: expected ", std::to_string(TS_DETAIL_LAYERS),
                    " (grass, dirt, rock, snow), got ", std::to_string(layers.size()));
    const uint32_t size = layers[0].width;
    for (size_t i = 0; i < layers.size(); ++i) {
        const Rgba8Image& image = layers[i];
        if (image.width != size || image.height != size || (size & (size - 1)) != 0 ||
            image.pixels.size() != size_t(size) * size * 4)
            return fail("terrain detail texture ", kLayerNames[i], ": ", std::to_string(image.width), "x",
                        std::to_string(image.height), ", expected square power-of-two images of one size (",
                        std::to_string(size), "x", std::to_string(size), ")");
    }

    std::vector<std::span<const uint8_t>> levels;
    for (const Rgba8Image& image : layers) levels.emplace_back(image.pixels);
    std::vector<std::array<uint8_t, 4>> smallest;
    DetailTextureArray array;
    array.image = makeMippedRgba8(device, levels, size, size, VK_FORMAT_R8G8B8A8_SRGB, core::MipEncoding::Srgb,
                                  "terrain.detailTextures", &smallest);
    // Each layer's 1x1 level is its average.
    for (uint32_t layer = 0; layer < TS_DETAIL_LAYERS; ++layer) {
        const auto& c = smallest[layer];
        array.averages[layer] = glm::vec4(toLinear(c[0]), toLinear(c[1]), toLinear(c[2]), 1.0f);
    }
    return array;
}

} // namespace tessera::backends
