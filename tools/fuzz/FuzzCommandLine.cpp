// tessera-demo's command line (every flag, its value checks and the checks
// between flags) on arbitrary arguments: the input split at newlines and
// NULs into argv.
#include "tessera/demo/CommandLine.h"

#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::vector<std::string> args(1);
    for (size_t i = 0; i < size; ++i) {
        const char c = static_cast<char>(data[i]);
        if (c == '\n' || c == '\0') {
            args.emplace_back();
            continue;
        }
        args.back() += c;
    }
    if (args.back().empty()) args.pop_back();
    auto options = tessera::demo::parseCommandLine(args);
    (void)options;
    return 0;
}
