#include "GlbImageEncoder.h"

#include "tessera/core/ImageFile.h"

#include <bit>
#include <string>

namespace tessera::creature {

// R16 maps keep little-endian samples and the core's encoder takes uint16_t in
// the host's order: the two agree on every host Tessera builds for.
static_assert(std::endian::native == std::endian::little, "R16 texels are little-endian");

Result<std::vector<uint8_t>> encodePng(const character::TextureImage& image, const char* what) {
    using character::TextureFormat;
    if (image.empty()) return fail(what, ": empty image");
    size_t rowBytes = size_t(image.width) * image.bytesPerTexel();
    if (image.bytes.size() != rowBytes * image.height) {
        return fail(what, ": ", std::to_string(image.bytes.size()), " bytes for ", std::to_string(image.width), "x",
                    std::to_string(image.height), " texels");
    }
    const PngLayout layout = image.format == TextureFormat::R16 ? PngLayout::Gray16 : PngLayout::Rgba8;
    auto png = tessera::encodePng(PngPixels{image.width, image.height, layout, image.bytes.data()});
    if (!png) return fail(what, ": ", png.error().message);
    return png;
}

} // namespace tessera::creature
