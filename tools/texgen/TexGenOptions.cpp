#include "TexGenOptions.h"

#include "tessera/cli/CommandLine.h"
#include "tessera/cli/Validators.h"

#include <bit>
#include <limits>

namespace tessera::texgen {
namespace {

constexpr const char* kDescription =
    "Generates the terrain's tileable detail textures (grass, dirt, rock and snow albedo, sRGB RGBA8 PNGs named "
    "detail_<material>.png). The same options always give byte-identical files.";

void declare(cli::CommandLine& line, TexGenOptions& o, std::string& outDir) {
    CLI::App& app = line.app();
    app.add_option("--out-dir", outDir, "folder the four PNGs are written to (required; created if missing)")
        ->type_name("DIR")
        ->check(cli::nonEmpty());
    app.add_option("--size", o.size, "texels per side, a power of two in 16..4096 (default 512)")
        ->type_name("N")
        ->check(cli::count(16, 4096));
    app.add_option("--seed", o.seed, "pattern seed, 0..2^64-1 (default 1)")
        ->type_name("S")
        ->check(cli::count(0, std::numeric_limits<uint64_t>::max()));
    app.add_flag("--quiet", o.quiet, "no summary line");
}

} // namespace

std::string texGenUsage() {
    cli::CommandLine line("tessera-texgen", kDescription);
    TexGenOptions options;
    std::string outDir;
    declare(line, options, outDir);
    return line.help();
}

Result<TexGenOptions> parseTexGenOptions(int argc, const char* const* argv) {
    cli::CommandLine line("tessera-texgen", kDescription);
    TexGenOptions options;
    std::string outDir;
    declare(line, options, outDir);
    auto parsed = line.parse(argc, argv);
    if (!parsed) return parsed.error();
    if (!parsed.value()) {
        options.help = true;
        return options;
    }
    if (!std::has_single_bit(options.size))
        return fail("--size must be a power of two between 16 and 4096, got ", std::to_string(options.size));
    if (outDir.empty()) return fail("--out-dir DIR is required");
    options.outDir = outDir;
    return options;
}

} // namespace tessera::texgen
