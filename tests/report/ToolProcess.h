#pragma once
/// @file ToolProcess.h
/// Runs a program (tessera-report, chromium) and captures its output.

#include <cstdio>
#include <string>
#include <sys/wait.h>
#include <vector>

namespace tessera::test {

struct ToolResult {
    int exitCode = -1;  ///< -1: it did not exit normally (a crash)
    std::string output; ///< stdout and stderr together
};

inline std::string quoteArg(const std::string& s) {
    std::string out = "'";
    for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

inline ToolResult runTool(const std::string& program, const std::vector<std::string>& args) {
    std::string command = quoteArg(program);
    for (const auto& a : args) {
        command += ' ';
        command += quoteArg(a);
    }
    command += " 2>&1";
    ToolResult result;
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) return result;
    char buffer[4096];
    size_t n;
    while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) result.output.append(buffer, n);
    const int status = pclose(pipe);
    result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return result;
}

/// Non-empty lines of `text`.
inline std::vector<std::string> linesOf(const std::string& text) {
    std::vector<std::string> lines;
    std::string line;
    for (char c : text) {
        if (c == '\n') {
            if (!line.empty()) lines.push_back(line);
            line.clear();
        } else {
            line += c;
        }
    }
    if (!line.empty()) lines.push_back(line);
    return lines;
}

} // namespace tessera::test
