#include "tessera/core/ImageFile.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>

namespace tessera {

Status writePng(const std::filesystem::path& path, const PngPixels& pixels) {
    const std::string name = path.string();
    auto bytes = encodePng(pixels);
    if (!bytes) return fail(name, ": ", bytes.error().message);
    std::FILE* file = std::fopen(name.c_str(), "wb");
    if (!file) return fail(name, ": cannot open for writing: ", std::strerror(errno));
    bool ioError = std::fwrite(bytes->data(), 1, bytes->size(), file) != bytes->size();
    // fclose flushes; a full disk often shows up only here.
    ioError |= std::fclose(file) != 0;
    if (!ioError) return {};
    // A half-written PNG is removed, but only a regular file: the path may be
    // a device (/dev/full) or a pipe that is not ours to delete.
    std::error_code ignored;
    if (std::filesystem::is_regular_file(path, ignored)) std::filesystem::remove(path, ignored);
    return fail(name, ": write error (disk full?)");
}

Status writePng(const std::filesystem::path& path, const Rgba8Image& image) {
    if (image.width == 0 || image.height == 0 || image.pixels.size() != size_t(image.width) * image.height * 4)
        return fail(path.string(), ": cannot write an empty or inconsistent image");
    if (path.has_parent_path()) {
        std::error_code ec;
        std::filesystem::create_directories(path.parent_path(), ec);
    }
    return writePng(path, PngPixels{image.width, image.height, PngLayout::Rgba8, image.pixels.data()});
}

Result<Rgba8Image> readPng(const std::filesystem::path& path) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) return fail(path.string(), ": no such file");
    std::ifstream in(path, std::ios::binary);
    const std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    // stb's own words for a file it cannot open, as when it opened files itself.
    if (!in.is_open() || in.bad()) return fail(path.string(), ": not a readable image (can't fopen)");
    auto decoded = decodeImage(bytes, PngLayout::Rgba8);
    if (!decoded) return fail(path.string(), ": not a readable image (", decoded.error().message, ")");
    return Rgba8Image{decoded->width, decoded->height, std::move(decoded->bytes)};
}

} // namespace tessera
