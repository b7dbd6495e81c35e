// tessera-heightgen: writes a deterministic eroded-mountain height map.
// Exit status: 0 on success, 1 when the file cannot be written, 2 on a bad
// command line.

#include "HeightGenOptions.h"

#include "tessera/core/ProgressBar.h"
#include "tessera/terrain/HeightMapGenerator.h"
#include "tessera/terrain/HeightMapIO.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <system_error>

using namespace tessera;

int main(int argc, char** argv) {
    auto parsed = heightgen::parseHeightGenOptions(argc, argv);
    if (!parsed) {
        std::fprintf(stderr, "tessera-heightgen: %s\n%s", parsed.error().message.c_str(),
                     heightgen::heightGenUsage().c_str());
        return 2;
    }
    const heightgen::HeightGenOptions& options = *parsed;
    if (options.help) {
        std::fputs(heightgen::heightGenUsage().c_str(), stdout);
        return 0;
    }

    // The build writes into a fresh build tree; create the folders it names.
    if (options.out.has_parent_path()) {
        std::error_code ec;
        std::filesystem::create_directories(options.out.parent_path(), ec);
        if (ec) {
            std::fprintf(stderr, "tessera-heightgen: %s: cannot create folder: %s\n",
                         options.out.parent_path().string().c_str(), ec.message().c_str());
            return 1;
        }
    }

    terrain::HeightMapGeneratorSettings settings;
    settings.size = options.size;
    settings.seed = options.seed;
    settings.erosionDroplets = options.erosionDroplets;
    settings.threadCount = options.threads;

    const auto start = std::chrono::steady_clock::now();
    // A log gets a line per stage and per quarter of the run.
    core::ProgressBar bar(stderr, "tessera-heightgen", options.quiet, 25);
    std::vector<uint16_t> samples = terrain::generateHeightMap(
        settings, [&bar](std::string_view stage, float fraction) { bar.update(stage, fraction); });
    bar.finish();

    Status saved = terrain::saveHeightMapPng16(options.out, options.size, options.size, samples);
    if (!saved) {
        std::fprintf(stderr, "tessera-heightgen: %s\n", saved.error().message.c_str());
        return 1;
    }
    if (!options.quiet) {
        std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
        std::fprintf(stderr, "tessera-heightgen: wrote %s (%ux%u, seed %llu) in %.1f s\n",
                     options.out.string().c_str(), options.size, options.size,
                     static_cast<unsigned long long>(options.seed), elapsed.count());
    }
    return 0;
}
