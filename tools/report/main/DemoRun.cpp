#include "DemoRun.h"

#include "report/BenchInput.h"

#include <cerrno>
#include <cstring>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace tessera::reporttool {
namespace {

namespace fs = std::filesystem;

std::string commandLine(const std::vector<std::string>& args) {
    std::string out;
    for (const auto& a : args) out += (out.empty() ? "" : " ") + a;
    return out;
}

/// Runs `args` (args[0] the program) and waits; the child inherits stdout
/// and stderr, so the demo's table and log reach the user.
Status runProcess(const std::vector<std::string>& args) {
    std::vector<char*> argv;
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    std::fprintf(stderr, "tessera-report: running %s\n", commandLine(args).c_str());
    std::fflush(stderr);
    const pid_t pid = fork();
    if (pid < 0) return fail("cannot start ", args[0], ": ", std::strerror(errno));
    if (pid == 0) {
        execv(argv[0], argv.data());
        std::fprintf(stderr, "tessera-report: cannot run %s: %s\n", argv[0], std::strerror(errno));
        _exit(127);
    }
    int status = 0;
    while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR) return fail("waiting for ", args[0], ": ", std::strerror(errno));
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return {};
    if (WIFEXITED(status)) return fail(commandLine(args), ": exited with status ", std::to_string(WEXITSTATUS(status)));
    return fail(commandLine(args), ": killed by signal ", std::to_string(WTERMSIG(status)));
}

} // namespace

Result<fs::path> findDemo(const ReportOptions& options) {
    fs::path demo = options.demo;
    if (demo.empty()) {
        std::error_code ec;
        const fs::path self = fs::read_symlink("/proc/self/exe", ec);
        if (ec) return fail("cannot find tessera-report's own folder (", ec.message(), "); pass --demo FILE");
        demo = self.parent_path() / "tessera-demo";
    }
    if (access(demo.c_str(), X_OK) != 0)
        return fail(demo.string(), ": no tessera-demo to run (build it, or pass --demo FILE)");
    return demo;
}

Status runDemo(const ReportOptions& o, const fs::path& demo) {
    const report::InputLayout layout{o.dir};
    std::error_code ec;
    fs::create_directories(o.dir, ec);
    if (ec) return fail(o.dir.string(), ": cannot create the folder: ", ec.message());
    const std::string width = std::to_string(o.width), height = std::to_string(o.height);
    std::vector<std::string> bench = {demo.string(), "--bench", "terrain", "--backend", "all"};
    bench.insert(bench.end(), {"--out", layout.bench().string(), "--out-dir", o.dir.string()});
    bench.insert(bench.end(), {"--width", width, "--height", height});
    bench.insert(bench.end(), {"--frames", std::to_string(o.frames), "--warmup", std::to_string(o.warmup)});
    if (!o.device.empty()) bench.insert(bench.end(), {"--device", o.device});
    if (auto ran = runProcess(bench); !ran) return ran;
    // The screenshots of the backends the benchmark could run.
    auto records = report::loadBenchRecords(layout.bench());
    if (!records) return records.error();
    for (const std::string& backend : report::backendsOf(records.value())) {
        std::vector<std::string> shot = {demo.string(), "--scene", "terrain", "--backend", backend, "--camera",
                                         o.camera, "--width", width, "--height", height,
                                         // The comparison's common cap: the three draw the same levels.
                                         "--tess-max", "14.99", "--frames", "2", "--screenshot",
                                         layout.screenshot(backend).string()};
        if (!o.device.empty()) shot.insert(shot.end(), {"--device", o.device});
        if (auto ran = runProcess(shot); !ran) return ran;
    }
    return {};
}

} // namespace tessera::reporttool
