#pragma once
/// @file Reporter.h
/// How the runtime's errors and warnings reach the person running it, in
/// the host's words.
///
/// The runtime words every message itself and names the caller's settings
/// in its own words (Settings.h). A host that takes the settings under other
/// names, as tessera-demo takes them as flags, overrides name() and passes
/// its reporter in Options::reporter: the leading setting of an error or
/// warning (Error::setting) and the settings the runtime's advice names are
/// then spelled the host's way. Without one, messages go to the log as the
/// runtime words them.

#include "tessera/core/Result.h"

#include <string>
#include <string_view>

namespace tessera::runtime {

struct Options;

class Reporter {
public:
    virtual ~Reporter() = default;

    /// The host's name for the setting the runtime calls `words` (one of
    /// setting::all()); the words themselves unless overridden.
    virtual std::string name(std::string_view words) const;
    /// A problem that ended the run (runtime::execute returns 1): to the
    /// log as an error, worded by wording().
    virtual void error(const Error& error) const;
    /// A problem that only degrades the run (a capture that cannot be made,
    /// a feature the device lacks): to the log as a warning, worded by
    /// wording().
    virtual void warning(const Error& warning) const;

    /// `problem`'s message with its leading setting named by name().
    std::string wording(const Error& problem) const { return problem.naming(name(problem.setting)); }
};

/// The reporter `options` name (Options::reporter), or the runtime's own,
/// which logs messages as the runtime words them.
const Reporter& reporterFor(const Options& options);

} // namespace tessera::runtime
