#include "tessera/runtime/Reporter.h"

#include "tessera/runtime/Options.h"
#include "tessera/core/Log.h"

namespace tessera::runtime {

std::string Reporter::name(std::string_view words) const { return std::string(words); }

void Reporter::error(const Error& error) const { log::error(wording(error)); }

void Reporter::warning(const Error& warning) const { log::warning(wording(warning)); }

const Reporter& reporterFor(const Options& options) {
    static const Reporter runtimeWords;
    return options.reporter ? *options.reporter : runtimeWords;
}

} // namespace tessera::runtime
