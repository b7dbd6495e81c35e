#include "HeightGenOptions.h"

#include "tessera/cli/CommandLine.h"
#include "tessera/cli/Validators.h"
#include "tessera/terrain/HeightMapGenerator.h"

#include <bit>
#include <limits>

namespace tessera::heightgen {
namespace {

constexpr const char* kDescription =
    "Generates an eroded mountain height map as a 16-bit grayscale PNG. The same options always give "
    "byte-identical files.";

/// Declares the tool's flags on `line`, bound to `o`; `out` and `droplets`
/// are read as text and numbers first (required, and optional).
void declare(cli::CommandLine& line, HeightGenOptions& o, std::string& out, uint32_t& droplets) {
    CLI::App& app = line.app();
    app.add_option("--out", out, "output PNG path (required; parent folders are created)")
        ->type_name("FILE")
        ->check(cli::nonEmpty());
    app.add_option("--size", o.size, "samples per side, a power of two in 64..8192 (default 2048)")
        ->type_name("N")
        ->check(cli::count(terrain::kMinGeneratedSize, terrain::kMaxGeneratedSize));
    app.add_option("--seed", o.seed, "landscape seed, 0..2^64-1 (default 1)")
        ->type_name("S")
        ->check(cli::count(0, std::numeric_limits<uint64_t>::max()));
    app.add_option("--erosion-droplets", droplets, "hydraulic erosion droplets (default size*size/4; 0 = none)")
        ->type_name("N")
        ->check(cli::count(0, std::numeric_limits<uint32_t>::max()));
    app.add_option("--threads", o.threads, "worker threads, 0 = all (default 0; never changes the output)")
        ->type_name("N")
        ->check(cli::count(0, 1024));
    app.add_flag("--quiet", o.quiet, "no progress bar and no summary line");
}

} // namespace

std::string heightGenUsage() {
    cli::CommandLine line("tessera-heightgen", kDescription);
    HeightGenOptions options;
    std::string out;
    uint32_t droplets = 0;
    declare(line, options, out, droplets);
    return line.help();
}

Result<HeightGenOptions> parseHeightGenOptions(int argc, const char* const* argv) {
    cli::CommandLine line("tessera-heightgen", kDescription);
    HeightGenOptions options;
    std::string out;
    uint32_t droplets = 0;
    declare(line, options, out, droplets);
    auto parsed = line.parse(argc, argv);
    if (!parsed) return parsed.error();
    if (!parsed.value()) {
        options.help = true;
        return options;
    }
    if (!std::has_single_bit(options.size))
        return fail("--size must be a power of two between 64 and 8192, got ", std::to_string(options.size));
    if (out.empty()) return fail("--out FILE is required");
    options.out = out;
    if (line.app().count("--erosion-droplets") > 0) options.erosionDroplets = droplets;
    return options;
}

} // namespace tessera::heightgen
