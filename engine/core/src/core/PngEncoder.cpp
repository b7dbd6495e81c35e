// encodePng (tessera/core/ImageFile.h): the code base's one PNG encoder, on
// libpng. Kept in a file of its own so libpng's setjmp error handling stays
// in one small, C-like place.

#include "tessera/core/ImageFile.h"

#include <png.h>

#include <csetjmp>
#include <cstdio>
#include <string>

namespace tessera {
namespace {

// Everything the setjmp-guarded code touches lives here, in memory owned by
// the caller: after a longjmp, locals of the guarded frame that changed since
// setjmp are indeterminate, but this struct is not.
struct PngJob {
    const PngPixels* pixels = nullptr;
    std::vector<uint8_t>* out = nullptr;
    unsigned char* row = nullptr; ///< one row of scratch, for the big-endian swap
    png_structp png = nullptr;
    png_infop info = nullptr;
    char message[256] = {};
};

[[noreturn]] void onPngError(png_structp png, png_const_charp message) {
    auto* job = static_cast<PngJob*>(png_get_error_ptr(png));
    std::snprintf(job->message, sizeof(job->message), "%s", message);
    // libpng requires the error callback not to return.
    png_longjmp(png, 1);
}

// libpng warnings (none are expected for these fixed formats) are not
// failures; swallow them instead of letting libpng print to stderr.
void onPngWarning(png_structp, png_const_charp) {}

void appendBytes(png_structp png, png_bytep data, png_size_t size) {
    auto* job = static_cast<PngJob*>(png_get_io_ptr(png));
    job->out->insert(job->out->end(), data, data + size);
}

void flushNothing(png_structp) {}

void writeRows(PngJob* job) {
    const PngPixels& p = *job->pixels;
    const bool sixteen = p.layout == PngLayout::Gray16;
    const int colorType = p.layout == PngLayout::Rgba8 ? PNG_COLOR_TYPE_RGBA : PNG_COLOR_TYPE_GRAY;
    png_set_write_fn(job->png, job, appendBytes, flushNothing);
    png_set_IHDR(job->png, job->info, p.width, p.height, sixteen ? 16 : 8, colorType, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    // Pin every choice libpng would otherwise leave to its defaults, so the
    // bytes depend only on the pixels (and the zlib build). The adaptive
    // filter heuristic is deterministic: it looks at the row's bytes only.
    png_set_compression_level(job->png, 6);
    png_set_filter(job->png, PNG_FILTER_TYPE_BASE, PNG_ALL_FILTERS);
    png_write_info(job->png, job->info);
    const size_t rowBytes = size_t(p.width) * bytesPerPixel(p.layout);
    const auto* bytes = static_cast<const unsigned char*>(p.data);
    for (uint32_t y = 0; y < p.height; ++y) {
        const unsigned char* src = bytes + rowBytes * y;
        if (sixteen) {
            // PNG stores 16-bit samples big-endian; convert by value instead
            // of png_set_swap() so the code does not depend on the host order.
            const auto* samples = reinterpret_cast<const uint16_t*>(src);
            for (uint32_t x = 0; x < p.width; ++x) {
                job->row[2 * x] = static_cast<unsigned char>(samples[x] >> 8);
                job->row[2 * x + 1] = static_cast<unsigned char>(samples[x] & 0xffu);
            }
            src = job->row;
        }
        png_write_row(job->png, src);
    }
    png_write_end(job->png, nullptr);
}

// The only function that calls setjmp. It has no C++ objects with destructors
// (a longjmp into it must not skip any) and reads only `job` after the jump.
bool encodeGuarded(PngJob* job) {
    job->png = png_create_write_struct(PNG_LIBPNG_VER_STRING, job, onPngError, onPngWarning);
    if (!job->png) {
        std::snprintf(job->message, sizeof(job->message), "libpng could not start");
        return false;
    }
    job->info = png_create_info_struct(job->png);
    if (!job->info) {
        png_destroy_write_struct(&job->png, nullptr);
        std::snprintf(job->message, sizeof(job->message), "libpng could not start");
        return false;
    }
    if (setjmp(png_jmpbuf(job->png))) {
        png_destroy_write_struct(&job->png, &job->info);
        return false;
    }
    writeRows(job);
    png_destroy_write_struct(&job->png, &job->info);
    return true;
}

} // namespace

uint32_t bytesPerPixel(PngLayout layout) {
    switch (layout) {
    case PngLayout::Rgba8: return 4;
    case PngLayout::Gray8: return 1;
    case PngLayout::Gray16: return 2;
    }
    return 4;
}

Result<std::vector<uint8_t>> encodePng(const PngPixels& pixels) {
    if (pixels.width == 0 || pixels.height == 0 || !pixels.data)
        return fail("cannot encode an empty PNG (", std::to_string(pixels.width), "x",
                    std::to_string(pixels.height), ")");
    if (pixels.width > 0x7fffffffu || pixels.height > 0x7fffffffu) return fail("image too large for PNG");
    std::vector<unsigned char> row(size_t(pixels.width) * 2);
    std::vector<uint8_t> out;
    PngJob job;
    job.pixels = &pixels;
    job.out = &out;
    job.row = row.data();
    if (!encodeGuarded(&job)) return fail("PNG encoding failed (", job.message, ")");
    return out;
}

} // namespace tessera
