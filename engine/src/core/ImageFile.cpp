#include "tessera/core/ImageFile.h"

#include <stb_image.h>
#include <stb_image_write.h>

#include <cerrno>
#include <cstring>
#include <fstream>

namespace tessera {

Status writePng(const std::filesystem::path& path, const Rgba8Image& image) {
    if (image.width == 0 || image.height == 0 || image.pixels.size() != size_t(image.width) * image.height * 4)
        return fail(path.string(), ": cannot write an empty or inconsistent image");
    if (path.has_parent_path()) {
        std::error_code ec;
        std::filesystem::create_directories(path.parent_path(), ec);
    }
    // stb reports no reason on failure; probe the path ourselves for one.
    {
        std::ofstream probe(path, std::ios::binary);
        if (!probe) return fail(path.string(), ": cannot open for writing: ", std::strerror(errno));
    }
    if (!stbi_write_png(path.c_str(), int(image.width), int(image.height), 4, image.pixels.data(), int(image.width * 4)))
        return fail(path.string(), ": failed to write the PNG");
    return {};
}

Result<Rgba8Image> readPng(const std::filesystem::path& path) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) return fail(path.string(), ": no such file");
    int w = 0, h = 0, channels = 0;
    stbi_uc* data = stbi_load(path.c_str(), &w, &h, &channels, 4);
    if (!data) return fail(path.string(), ": not a readable image (", stbi_failure_reason(), ")");
    Rgba8Image image;
    image.width = uint32_t(w);
    image.height = uint32_t(h);
    image.pixels.assign(data, data + size_t(w) * h * 4);
    stbi_image_free(data);
    return image;
}

} // namespace tessera
