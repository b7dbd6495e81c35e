#include "session/TerrainDetailTextures.h"

#include "world/ContentLocator.h"

namespace tessera::runtime {

Result<std::vector<Rgba8Image>> loadTerrainDetailTextures(const std::string& contentDir) {
    std::vector<Rgba8Image> layers;
    for (const char* material : {"grass", "dirt", "rock", "snow"}) {
        const std::string relative = std::string("terrain/detail_") + material + ".png";
        auto path = locateContent(contentDir, relative);
        if (!path) return fail("terrain detail texture: ", path.error().message);
        auto image = readPng(path.value());
        if (!image) return fail("terrain detail texture: ", image.error().message);
        const uint32_t size = image->width;
        const bool square = size == image->height && size >= 1 && (size & (size - 1)) == 0;
        if (!square || (!layers.empty() && size != layers.front().width))
            return fail("terrain detail texture ", path->string(), ": ", std::to_string(image->width), "x",
                        std::to_string(image->height),
                        ", expected a square power-of-two image the size of the others (rebuild the content: "
                        "tessera-texgen makes them)");
        layers.push_back(std::move(image.value()));
    }
    return layers;
}

} // namespace tessera::runtime
