#include "GlbImageEncoder.h"

#include <png.h>

#include <csetjmp>
#include <string>

namespace tessera::creature {

namespace {

void appendBytes(png_structp png, png_bytep data, png_size_t size) {
    auto* out = static_cast<std::vector<uint8_t>*>(png_get_io_ptr(png));
    out->insert(out->end(), data, data + size);
}

void flushNothing(png_structp) {}

// libpng reports failures by longjmp, which must not cross frames holding
// objects with destructors: this frame holds plain pointers only.
bool writePng(std::vector<uint8_t>* out, png_bytep* rows, uint32_t width, uint32_t height, int bitDepth,
              int colorType) {
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    if (!png) return false;
    png_infop info = png_create_info_struct(png);
    if (!info) {
        png_destroy_write_struct(&png, nullptr);
        return false;
    }
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        return false;
    }
    png_set_write_fn(png, out, appendBytes, flushNothing);
    png_set_IHDR(png, info, width, height, bitDepth, colorType, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    // Fixed settings: the file bytes must not depend on libpng's defaults
    // changing between builds of the same version.
    png_set_compression_level(png, 6);
    png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_ALL_FILTERS);
    png_write_info(png, info);
    png_write_image(png, rows);
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    return true;
}

} // namespace

Result<std::vector<uint8_t>> encodePng(const character::TextureImage& image, const char* what) {
    using character::TextureFormat;
    if (image.empty()) return fail(what, ": empty image");
    size_t rowBytes = size_t(image.width) * image.bytesPerTexel();
    if (image.bytes.size() != rowBytes * image.height) {
        return fail(what, ": ", std::to_string(image.bytes.size()), " bytes for ", std::to_string(image.width), "x",
                    std::to_string(image.height), " texels");
    }
    if (image.width > 0x7fffffffu || image.height > 0x7fffffffu) return fail(what, ": image too large for PNG");

    // PNG stores 16-bit samples big-endian; the texture keeps them little-endian.
    std::vector<uint8_t> swapped;
    const uint8_t* texels = image.bytes.data();
    if (image.format == TextureFormat::R16) {
        swapped.resize(image.bytes.size());
        for (size_t i = 0; i + 1 < image.bytes.size(); i += 2) {
            swapped[i] = image.bytes[i + 1];
            swapped[i + 1] = image.bytes[i];
        }
        texels = swapped.data();
    }
    std::vector<png_bytep> rows(image.height);
    for (uint32_t y = 0; y < image.height; ++y) rows[y] = const_cast<png_bytep>(texels + y * rowBytes);

    std::vector<uint8_t> out;
    bool ok = image.format == TextureFormat::R16
                  ? writePng(&out, rows.data(), image.width, image.height, 16, PNG_COLOR_TYPE_GRAY)
                  : writePng(&out, rows.data(), image.width, image.height, 8, PNG_COLOR_TYPE_RGBA);
    if (!ok) return fail(what, ": PNG encoding failed");
    return out;
}

} // namespace tessera::creature
