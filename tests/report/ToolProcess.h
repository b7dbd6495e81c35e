#pragma once
/// @file ToolProcess.h
/// What the report tests need beyond DemoProcess.h's runProgram (which runs
/// tessera-report and chromium): the non-empty lines of an output.

#include "DemoProcess.h"

#include <string>
#include <vector>

namespace tessera::test {

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
