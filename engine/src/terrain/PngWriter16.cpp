#include "PngWriter16.h"

#include <csetjmp>
#include <cstdio>
#include <string>
#include <vector>

#include <png.h>

namespace tessera::terrain {
namespace {

// Everything the setjmp-guarded code touches lives here, in memory owned by
// the caller: after a longjmp, locals of the guarded frame that changed since
// setjmp are indeterminate, but this struct is not.
struct PngJob {
    std::FILE* file = nullptr;
    const uint16_t* samples = nullptr;
    uint32_t width = 0;
    uint32_t height = 0;
    unsigned char* row = nullptr; ///< width * 2 bytes of scratch.
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

// libpng warnings (none are expected for this fixed format) are not failures;
// swallow them instead of letting libpng print to stderr.
void onPngWarning(png_structp, png_const_charp) {}

void writeRows(PngJob* job) {
    png_init_io(job->png, job->file);
    png_set_IHDR(job->png, job->info, job->width, job->height, 16, PNG_COLOR_TYPE_GRAY,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    // Pin every choice libpng would otherwise make adaptively or by default,
    // so the bytes depend only on the samples (and the zlib build).
    png_set_compression_level(job->png, 6);
    png_set_filter(job->png, PNG_FILTER_TYPE_BASE, PNG_FILTER_PAETH);
    png_write_info(job->png, job->info);
    for (uint32_t j = 0; j < job->height; ++j) {
        const uint16_t* src = job->samples + size_t(j) * job->width;
        // PNG stores 16-bit samples big-endian; convert explicitly instead of
        // png_set_swap() so the code does not depend on the host byte order.
        for (uint32_t i = 0; i < job->width; ++i) {
            job->row[2 * i] = static_cast<unsigned char>(src[i] >> 8);
            job->row[2 * i + 1] = static_cast<unsigned char>(src[i] & 0xffu);
        }
        png_write_row(job->png, job->row);
    }
    png_write_end(job->png, nullptr);
}

// The only function that calls setjmp. It has no C++ objects with destructors
// (a longjmp into it must not skip any) and reads only `job` after the jump.
bool writeGuarded(PngJob* job) {
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

Status writePngGray16(const std::filesystem::path& path, uint32_t width, uint32_t height,
                      const uint16_t* samples) {
    const std::string name = path.string();
    std::FILE* file = std::fopen(name.c_str(), "wb");
    if (!file) return fail(name, ": cannot open for writing");

    std::vector<unsigned char> row(size_t(width) * 2);
    PngJob job;
    job.file = file;
    job.samples = samples;
    job.width = width;
    job.height = height;
    job.row = row.data();

    bool ok = writeGuarded(&job);
    // fclose flushes; a full disk often shows up only here.
    bool ioError = std::ferror(file) != 0;
    ioError |= std::fclose(file) != 0;
    if (ok && !ioError) return {};

    std::error_code ignored;
    std::filesystem::remove(path, ignored);
    if (!ok) return fail(name, ": cannot write PNG (", job.message, ")");
    return fail(name, ": write error (disk full?)");
}

} // namespace tessera::terrain
