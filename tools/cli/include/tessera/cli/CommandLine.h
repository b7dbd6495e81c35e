#pragma once
/// @file CommandLine.h
/// The one command-line parser of tessera-demo and every tool, over CLI11.
///
/// A program declares its options on app() with CLI11's own calls (and the
/// validators of Validators.h), then parse() reads argv. Every program gets
/// the same syntax, `--flag value` and `--flag=value`, the same help layout
/// (HelpFormatter) and the same one-line errors:
/// - `--width expects a whole number from 16 to 16384, got "5"`
/// - `--frames needs a value`
/// - `unknown option "--frobnicate"; run with --help for the list`

#include "tessera/core/Result.h"

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace tessera::cli {

class CommandLine {
public:
    /// `program` is the executable's name (for usage lines), `description`
    /// the paragraph --help prints first.
    CommandLine(std::string program, std::string description);

    /// Where the program declares its options and flags.
    CLI::App& app() { return mApp; }
    /// After parse(): which flags were given (`app().count("--flag")`).
    const CLI::App& app() const { return mApp; }

    /// Parses `args` (argv without argv[0]). true: run; false: --help or -h
    /// was given (print help()). An Error holds one line in the style above.
    Result<bool> parse(std::vector<std::string> args);
    /// The same from main's argc and argv.
    Result<bool> parse(int argc, const char* const* argv);

    /// The --help text, generated from the declared options.
    std::string help() const;

private:
    CLI::App mApp;
};

} // namespace tessera::cli
