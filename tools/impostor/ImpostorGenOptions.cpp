#include "ImpostorGenOptions.h"

#include "tessera/cli/CommandLine.h"
#include "tessera/cli/Validators.h"

namespace tessera::impostorgen {
namespace {

constexpr const char* kDescription =
    "Bakes a character's impostor atlas (its cage from 8 x 8 view directions at 8 phases of every clip, 32-texel "
    "cells, base colour with coverage and normals, 4 mips) into a .impostor file. The same input always gives "
    "byte-identical files.";

void declare(cli::CommandLine& line, ImpostorGenOptions& o, std::string& in, std::string& out) {
    CLI::App& app = line.app();
    app.add_option("--in", in, "the character, a .glb or .gltf file (required)")
        ->type_name("FILE")
        ->check(cli::nonEmpty());
    app.add_option("--out", out, "the .impostor file to write (default: --in's path with the extension .impostor)")
        ->type_name("FILE")
        ->check(cli::nonEmpty());
    app.add_option("--threads", o.threads, "worker threads, 0 = all (default 0; never changes the output)")
        ->type_name("N")
        ->check(cli::count(0, 1024));
    app.add_flag("--quiet", o.quiet, "no summary line");
}

} // namespace

std::string impostorGenUsage() {
    cli::CommandLine line("tessera-impostorgen", kDescription);
    ImpostorGenOptions options;
    std::string in, out;
    declare(line, options, in, out);
    return line.help();
}

Result<ImpostorGenOptions> parseImpostorGenOptions(int argc, const char* const* argv) {
    cli::CommandLine line("tessera-impostorgen", kDescription);
    ImpostorGenOptions options;
    std::string in, out;
    declare(line, options, in, out);
    auto parsed = line.parse(argc, argv);
    if (!parsed) return parsed.error();
    if (!parsed.value()) {
        options.help = true;
        return options;
    }
    if (in.empty()) return fail("--in FILE is required");
    options.in = in;
    options.out = out.empty() ? std::filesystem::path(in).replace_extension(".impostor") : std::filesystem::path(out);
    return options;
}

} // namespace tessera::impostorgen
