#include "ReportOptions.h"

#include "tessera/cli/CameraPoseText.h"
#include "tessera/cli/CommandLine.h"
#include "tessera/cli/Validators.h"

namespace tessera::reporttool {
namespace {

constexpr const char* kDescription =
    "Writes the backends' comparison as one self-contained HTML file (inline SVG charts, screenshots and their "
    "diffs against hulldomain, flagged timings) and report-trace.json, every backend's trace on one timeline. "
    "Reads DIR/bench.json, DIR/bench-<backend>.json and DIR/screenshot-<backend>.png, or makes them first with "
    "--run. Exit status: 0 written, 1 an input or a run failed, 2 a bad command line.";

struct Text {
    std::string dir, out, demo;
};

void declare(cli::CommandLine& line, ReportOptions& o, Text& t) {
    CLI::App& app = line.app();
    app.add_option("--dir", t.dir, "the inputs' folder; with --run, where the run writes them (required)")
        ->type_name("DIR")
        ->check(cli::nonEmpty());
    app.add_option("--out", t.out, "the HTML file (default DIR/report.html); report-trace.json goes beside it")
        ->type_name("FILE")
        ->check(cli::nonEmpty());
    app.add_flag("--run", o.run,
                 "run tessera-demo first: the terrain benchmark on every backend (--backend all) and one "
                 "screenshot per backend");
    app.add_option("--width", o.width, "--run's render width (default 1280)")
        ->type_name("N")
        ->check(cli::count(16, 16384));
    app.add_option("--height", o.height, "--run's render height (default 720)")
        ->type_name("N")
        ->check(cli::count(16, 16384));
    app.add_option("--frames", o.frames, "--run's measured frames per row (default 10)")
        ->type_name("N")
        ->check(cli::count(1, 100000));
    app.add_option("--warmup", o.warmup, "--run's warm-up frames per row (default 3)")
        ->type_name("N")
        ->check(cli::count(0, 100000));
    app.add_option("--camera", o.camera, "--run's screenshot view, x,y,z,yaw,pitch (default 1800,900,6800,-30,-16)")
        ->type_name("x,y,z,yaw,pitch");
    app.add_option("--device", o.device, "--run's Vulkan device (index or name substring)")->type_name("NAME|INDEX");
    app.add_option("--demo", t.demo, "the tessera-demo to run (default: the one next to tessera-report)")
        ->type_name("FILE")
        ->check(cli::nonEmpty());
    app.add_option("--min-main-share", o.minMainPassPercent,
                   "on a CPU device, flag a main terrain pass under this percentage of the wall-clock frame "
                   "(default 2)")
        ->type_name("PCT")
        ->check(cli::number(0, 100));
    app.add_option("--min-gpu-share", o.minGpuFramePercent,
                   "on a CPU device, flag the main terrain pass where all GPU passes make up less than this "
                   "percentage of the wall-clock frame (default 50)")
        ->type_name("PCT")
        ->check(cli::number(0, 100));
}

} // namespace

std::string reportUsage() {
    cli::CommandLine line("tessera-report", kDescription);
    ReportOptions o;
    Text t;
    declare(line, o, t);
    return line.help();
}

Result<ReportOptions> parseReportOptions(int argc, const char* const* argv) {
    cli::CommandLine line("tessera-report", kDescription);
    ReportOptions o;
    Text t;
    declare(line, o, t);
    auto parsed = line.parse(argc, argv);
    if (!parsed) return parsed.error();
    if (!parsed.value()) {
        o.help = true;
        return o;
    }
    if (t.dir.empty()) return fail("--dir DIR is required");
    // The view goes to tessera-demo; read it as the demo does, so a typo
    // stops here rather than after the benchmark's run.
    if (auto pose = cli::parseCameraPose(o.camera); !pose) return pose.error();
    o.dir = t.dir;
    o.out = t.out.empty() ? o.dir / "report.html" : std::filesystem::path(t.out);
    o.demo = t.demo;
    const bool runOnly = line.app().count("--width") + line.app().count("--height") + line.app().count("--frames") +
                             line.app().count("--warmup") + line.app().count("--device") + line.app().count("--demo") >
                         0;
    if (runOnly && !o.run) return fail("--width, --height, --frames, --warmup, --device and --demo need --run");
    return o;
}

} // namespace tessera::reporttool
