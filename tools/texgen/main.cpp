// tessera-texgen: writes the terrain's four tileable detail textures.
// Exit status: 0 on success, 1 when a file cannot be written, 2 on a bad
// command line.

#include "DetailTextureGenerator.h"
#include "TexGenOptions.h"

#include "tessera/core/ImageFile.h"

#include <cstdio>
#include <filesystem>
#include <string>
#include <system_error>

using namespace tessera;

int main(int argc, char** argv) {
    auto parsed = texgen::parseTexGenOptions(argc, argv);
    if (!parsed) {
        std::fprintf(stderr, "tessera-texgen: %s\n%s", parsed.error().message.c_str(), texgen::texGenUsage().c_str());
        return 2;
    }
    const texgen::TexGenOptions& options = *parsed;
    if (options.help) {
        std::fputs(texgen::texGenUsage().c_str(), stdout);
        return 0;
    }
    std::error_code ec;
    std::filesystem::create_directories(options.outDir, ec);
    if (ec) {
        std::fprintf(stderr, "tessera-texgen: %s: cannot create folder: %s\n", options.outDir.string().c_str(),
                     ec.message().c_str());
        return 1;
    }
    for (const auto material : texgen::kDetailMaterials) {
        const std::filesystem::path file =
            options.outDir / ("detail_" + std::string(texgen::materialName(material)) + ".png");
        Status written = writePng(file, texgen::generateDetailTexture(material, options.size, options.seed));
        if (!written) {
            std::fprintf(stderr, "tessera-texgen: %s\n", written.error().message.c_str());
            return 1;
        }
        if (!options.quiet)
            std::fprintf(stderr, "tessera-texgen: wrote %s (%ux%u, seed %llu)\n", file.string().c_str(), options.size,
                         options.size, static_cast<unsigned long long>(options.seed));
    }
    return 0;
}
