#pragma once
/// @file DemoProcess.h
/// Runs tessera-demo, or any program, as a child process and captures its
/// output.

#include <cstdio>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <vector>

namespace tessera::test {

struct ProcessResult {
    int exitCode = -1;
    std::string output; ///< stdout and stderr together
};

inline std::string shellQuote(const std::string& s) {
    std::string out = "'";
    for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

/// Runs `program` with `args` through the shell, `environment` (assignments
/// such as `A=1 `) before it; the exit code is -1 if it did not exit normally
/// (a crash), so tests can tell a clean failure from a crash.
inline ProcessResult runProgram(const std::string& program, const std::vector<std::string>& args,
                                const std::string& environment = {}) {
    std::string command = environment + shellQuote(program);
    for (const auto& a : args) {
        command += ' ';
        command += shellQuote(a);
    }
    command += " 2>&1";
    ProcessResult result;
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) return result;
    char buffer[4096];
    size_t n;
    while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) result.output.append(buffer, n);
    const int status = pclose(pipe);
    result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return result;
}

#ifdef TESSERA_DEMO_EXE
/// Runs the demo with `args`.
inline ProcessResult runDemo(const std::vector<std::string>& args) {
    // Under ./tessera test --sanitize the demo still runs with ASan and UBSan,
    // but without leak checking: the Vulkan loader unloads the driver before
    // exit, so the driver's own process-lifetime allocations show up as leaks
    // from "<unknown module>" that no suppression can name. Leak checking stays
    // on for the unit tests, which cover the engine without a driver.
    return runProgram(TESSERA_DEMO_EXE, args, "ASAN_OPTIONS=\"${ASAN_OPTIONS:-}:detect_leaks=0\" ");
}
#endif

/// Whether a run failed only because the device cannot run the backend it
/// asked for (meshshader on a device without mesh shaders): the demo says so
/// with this hint. Tests that name every backend skip such a backend.
inline bool deviceCannotRun(const ProcessResult& result) {
    return result.exitCode != 0 &&
           result.output.find("run --list-backends to see which backends this device runs") != std::string::npos;
}

#ifdef TESSERA_DEMO_EXE
/// Whether the default device runs `backend`, from --list-backends (asked
/// once per process): tests that name every backend skip the ones it cannot.
inline bool deviceRunsBackend(const std::string& backend) {
    static const std::string listing = runDemo({"--list-backends"}).output;
    std::istringstream in(listing);
    for (std::string line; std::getline(in, line);) {
        std::istringstream words(line);
        std::string name, state;
        if (words >> name >> state && name == backend) return state == "ok";
    }
    return false;
}
#endif

/// The log's error lines ("tessera: error: ...") in a run's output.
inline std::vector<std::string> errorLines(const std::string& output) {
    std::vector<std::string> lines;
    std::istringstream in(output);
    for (std::string line; std::getline(in, line);)
        if (line.find("tessera: error:") != std::string::npos) lines.push_back(line);
    return lines;
}

} // namespace tessera::test
