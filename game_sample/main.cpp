// tessera-demo: the crowd/terrain demo's entry point.
#include "tessera/runtime/Runner.h"
#include "CommandLine.h"
#include "tessera/core/Log.h"

#include <cstdio>

int main(int argc, char** argv) {
    std::vector<std::string> args(argv + 1, argv + argc);
    auto options = tessera::demo::parseCommandLine(args);
    if (!options) {
        tessera::log::error(options.error().message);
        return 2;
    }
    if (options->help) {
        std::fputs(tessera::demo::helpText().c_str(), stdout);
        return 0;
    }
    return tessera::runtime::execute(options.value());
}
