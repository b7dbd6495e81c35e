// The one image decoder (ImageFile.h): stb_image, from memory.
#include "tessera/core/ImageFile.h"

#include <stb_image.h>

#include <climits>
#include <memory>

namespace tessera {
namespace {

struct StbFree {
    void operator()(void* pixels) const { stbi_image_free(pixels); }
};

/// The decoder's reason for its last failure.
const char* failureReason() {
    const char* reason = stbi_failure_reason();
    return reason ? reason : "unknown decoder failure";
}

/// stb takes the length as an int.
Status checkLength(std::span<const uint8_t> bytes) {
    if (bytes.size() > size_t(INT_MAX)) return fail("image is too large");
    return {};
}

} // namespace

Result<ImageHeader> readImageHeader(std::span<const uint8_t> bytes) {
    if (Status length = checkLength(bytes); !length) return length.error();
    const int size = int(bytes.size());
    int w = 0, h = 0, channels = 0;
    if (!stbi_info_from_memory(bytes.data(), size, &w, &h, &channels)) return fail(failureReason());
    return ImageHeader{uint32_t(w), uint32_t(h), uint32_t(channels), stbi_is_16_bit_from_memory(bytes.data(), size) != 0};
}

Result<DecodedImage> decodeImage(std::span<const uint8_t> bytes, PngLayout layout) {
    if (Status length = checkLength(bytes); !length) return length.error();
    const int size = int(bytes.size());
    const int channels = layout == PngLayout::Rgba8 ? 4 : 1;
    int w = 0, h = 0, stored = 0;
    // stb converts: channels to the ones asked for, and 8-bit samples to 16
    // bits by replicating the byte (v * 257) or 16-bit ones to their high byte.
    std::unique_ptr<void, StbFree> pixels(
        layout == PngLayout::Gray16
            ? static_cast<void*>(stbi_load_16_from_memory(bytes.data(), size, &w, &h, &stored, channels))
            : static_cast<void*>(stbi_load_from_memory(bytes.data(), size, &w, &h, &stored, channels)));
    if (!pixels) return fail(failureReason());
    DecodedImage image{uint32_t(w), uint32_t(h), layout, {}};
    const auto* first = static_cast<const uint8_t*>(pixels.get());
    image.bytes.assign(first, first + size_t(w) * size_t(h) * bytesPerPixel(layout));
    return image;
}

} // namespace tessera
