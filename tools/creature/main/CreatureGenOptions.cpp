#include "CreatureGenOptions.h"

#include "tessera/cli/CommandLine.h"
#include "tessera/cli/Validators.h"

namespace tessera::creature {
namespace {

constexpr const char* kDescription =
    "Generates a Froblin-like creature, bakes its displacement and normal maps and writes a glTF 2.0 binary "
    "(Draco-compressed cage unless --uncompressed).";

/// Declares the tool's flags on `line`, bound to `o`; the paths as text.
void declare(cli::CommandLine& line, CreatureGenOptions& o, std::string& out, std::string& report) {
    CLI::App& app = line.app();
    app.add_option("--seed", o.seed, "creature seed (default 1)")->type_name("N")->check(cli::count(0, UINT32_MAX));
    app.add_option("--out", out, "the .glb to write (required)")->type_name("FILE.glb")->check(cli::nonEmpty());
    app.add_option("--map-size", o.mapSize, "displacement and normal map size, 64..2048 (default 2048)")
        ->type_name("N")
        ->check(cli::count(64, 2048));
    app.add_option("--sculpt-triangles", o.sculptTriangles, "the sculpt's triangles, 10000..20000000 (default 1000000)")
        ->type_name("N")
        ->check(cli::count(10'000, 20'000'000));
    app.add_option("--cage-triangles", o.cageTriangles, "the cage's triangles, 500..50000 (default 5000)")
        ->type_name("N")
        ->check(cli::count(500, 50'000));
    app.add_option("--report", report, "also write the Table 1 report (JSON)")
        ->type_name("FILE.json")
        ->check(cli::nonEmpty());
    app.add_flag("--uncompressed", o.uncompressed, "store the cage without Draco");
    app.add_flag("--quiet", o.quiet, "no progress bar or summary");
}

} // namespace

Result<CreatureGenOptions> parseCreatureGenOptions(int argc, const char* const* argv) {
    cli::CommandLine line("tessera-creaturegen", kDescription);
    CreatureGenOptions o;
    std::string out, report;
    declare(line, o, out, report);
    auto parsed = line.parse(argc, argv);
    if (!parsed) return parsed.error();
    if (!parsed.value()) {
        o.help = true;
        return o;
    }
    if (out.empty()) return fail("--out FILE.glb is required");
    o.out = out;
    o.report = report;
    return o;
}

std::string creatureGenUsage() {
    cli::CommandLine line("tessera-creaturegen", kDescription);
    CreatureGenOptions o;
    std::string out, report;
    declare(line, o, out, report);
    return line.help();
}

} // namespace tessera::creature
