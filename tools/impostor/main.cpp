// tessera-impostorgen: bakes a character's impostor atlas into a .impostor
// file. Exit status: 0 on success, 1 when the character cannot be loaded or
// the file cannot be written, 2 on a bad command line.

#include "ImpostorGenOptions.h"

#include "tessera/assets/GltfLoader.h"
#include "tessera/character/ImpostorBaker.h"
#include "tessera/character/ImpostorFile.h"

#include <chrono>
#include <cstdio>

using namespace tessera;

int main(int argc, char** argv) {
    auto parsed = impostorgen::parseImpostorGenOptions(argc, argv);
    if (!parsed) {
        std::fprintf(stderr, "tessera-impostorgen: %s\n%s", parsed.error().message.c_str(),
                     impostorgen::impostorGenUsage().c_str());
        return 2;
    }
    const impostorgen::ImpostorGenOptions& options = *parsed;
    if (options.help) {
        std::fputs(impostorgen::impostorGenUsage().c_str(), stdout);
        return 0;
    }
    auto character = assets::loadCharacter(options.in);
    if (!character) {
        std::fprintf(stderr, "tessera-impostorgen: %s\n", character.error().message.c_str());
        return 1;
    }
    if (character->cage.triangleCount() == 0) {
        std::fprintf(stderr, "tessera-impostorgen: %s: has no triangles to draw\n", options.in.string().c_str());
        return 1;
    }
    const auto start = std::chrono::steady_clock::now();
    character::ImpostorBakeSettings settings;
    settings.threads = options.threads;
    const character::ImpostorAtlas atlas = character::bakeImpostors(*character, settings);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (Status written = character::writeImpostorFile(options.out, atlas); !written) {
        std::fprintf(stderr, "tessera-impostorgen: %s\n", written.error().message.c_str());
        return 1;
    }
    if (!options.quiet)
        std::fprintf(stderr, "tessera-impostorgen: wrote %s (%u layers, %.1f MiB) in %.2f s (%u cage triangles)\n",
                     options.out.string().c_str(), atlas.layers, double(atlas.bytes()) / (1024.0 * 1024.0), seconds,
                     character->cage.triangleCount());
    return 0;
}
