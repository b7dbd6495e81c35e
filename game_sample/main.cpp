// tessera-demo: the crowd/terrain demo's entry point.
#include "tessera/demo/CommandLine.h"
#include "tessera/demo/SettingFlags.h"
#include "tessera/core/Log.h"
#include "tessera/runtime/Reporter.h"
#include "tessera/runtime/Runner.h"

#include <cstdio>

namespace {

/// The runtime's messages with the demo's flags in place of the runtime's
/// words for its settings (SettingFlags.h).
class FlagReporter final : public tessera::runtime::Reporter {
public:
    std::string name(std::string_view words) const override { return tessera::demo::flagFor(words); }
};

} // namespace

int main(int argc, char** argv) {
    std::vector<std::string> args(argv + 1, argv + argc);
    auto options = tessera::demo::parseCommandLine(args);
    if (!options) {
        tessera::log::error(tessera::demo::withFlags(options.error()));
        return 2;
    }
    if (options->help) {
        std::fputs(tessera::demo::helpText().c_str(), stdout);
        return 0;
    }
    const FlagReporter reporter;
    options->reporter = &reporter;
    return tessera::runtime::execute(options.value());
}
