#include "tessera/cli/CommandLine.h"

#include "HelpFormatter.h"

#include <algorithm>

namespace tessera::cli {
namespace {

/// CLI11's messages in Tessera's one style (see CommandLine.h).
std::string restyle(const CLI::ParseError& e) {
    const std::string what = e.what();
    const std::string name = what.substr(0, what.find(':'));
    const bool named = name.rfind("-", 0) == 0 && name.find(' ') == std::string::npos && name.size() < what.size();
    if (dynamic_cast<const CLI::ExtrasError*>(&e)) {
        // "The following argument(s) was/were not expected: --foo bar"
        std::string extra = what.substr(what.find(": ") + 2);
        extra = extra.substr(0, extra.find(' '));
        return (extra.rfind("-", 0) == 0 ? "unknown option \"" : "unexpected argument \"") + extra +
               "\"; run with --help for the list";
    }
    if (what.find("disallowed flag override") != std::string::npos) {
        // CLI11 names the flag without its dashes here ("window was given ...").
        std::string flag = what.substr(0, what.find(' '));
        return (flag.rfind("-", 0) == 0 ? flag : "--" + flag) + " takes no value";
    }
    if (named && dynamic_cast<const CLI::ArgumentMismatch*>(&e)) return name + " needs a value";
    // "--flag: <validator's message>" reads "--flag <message>".
    if (named && what.compare(name.size(), 2, ": ") == 0) return name + " " + what.substr(name.size() + 2);
    return what;
}

} // namespace

CommandLine::CommandLine(std::string program, std::string description) : mApp(std::move(description), program) {
    mApp.formatter(std::make_shared<HelpFormatter>(program));
    mApp.option_defaults()->group("Options");
    // A flag given twice takes the last value, as a user retyping it means.
    mApp.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
    // Flags are on or absent: "--quiet=1" is a mistake to report, not a value.
    mApp.option_defaults()->disable_flag_override();
    mApp.set_help_flag("-h,--help", "this text");
}

Result<bool> CommandLine::parse(std::vector<std::string> args) {
    // CLI11 would take "--other" as the value of "--flag --other"; a flag
    // there means the value was forgotten ("--screenshot --window" must not
    // write a file named --window).
    for (size_t i = 0; i + 1 < args.size(); ++i) {
        if (args[i].rfind("--", 0) != 0 || args[i].find('=') != std::string::npos) continue;
        const CLI::Option* option = mApp.get_option_no_throw(args[i]);
        if (option && option->get_expected_min() > 0 && args[i + 1].rfind("--", 0) == 0)
            return fail(args[i], " needs a value");
    }
    // CLI11 takes the arguments last first.
    std::reverse(args.begin(), args.end());
    try {
        mApp.parse(args);
    } catch (const CLI::CallForHelp&) {
        return false;
    } catch (const CLI::ParseError& e) {
        return fail(restyle(e));
    }
    return true;
}

Result<bool> CommandLine::parse(int argc, const char* const* argv) {
    return parse(std::vector<std::string>(argv + (argc > 0 ? 1 : 0), argv + std::max(argc, 0)));
}

std::string CommandLine::help() const { return mApp.help(); }

} // namespace tessera::cli
