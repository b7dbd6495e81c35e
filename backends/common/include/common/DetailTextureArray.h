#pragma once
/// @file DetailTextureArray.h
/// The terrain's detail albedo textures on the GPU: one R8G8B8A8_SRGB 2D
/// array (a layer per material, TS_DETAIL_*) with a full mip chain, so the
/// sampler decodes sRGB to linear before filtering and the distant terrain
/// reads pre-averaged texels instead of shimmering.

#include "tessera/core/ImageFile.h"
#include "tessera/core/Result.h"
#include "tessera/gpu/Device.h"
#include "tessera/gpu/Image.h"

#include <array>
#include <glm/glm.hpp>
#include <span>

namespace tessera::backends {

class DetailTextureArray {
public:
    /// Uploads `layers` (TerrainDesc::detailTextures). Empty: a 1x1 layer per
    /// material holding its average colour, so shading needs no special case.
    /// Fails, naming the layer, on images that are not square, equal-sized
    /// powers of two, or on a count other than TS_DETAIL_LAYERS.
    static Result<DetailTextureArray> create(gpu::Device& device, std::span<const Rgba8Image> layers);

    gpu::Image image;
    /// Each layer's average albedo (linear rgb, its 1x1 mip), for TerrainUniforms.
    std::array<glm::vec4, 4> averages{};
};

} // namespace tessera::backends
