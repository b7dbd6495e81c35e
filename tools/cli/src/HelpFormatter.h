#pragma once
/// @file HelpFormatter.h
/// --help in one layout for every program: "usage:" line, description,
/// options by group, each flag with its argument's name in a 24-column
/// margin and its description wrapped to 79 columns beside it.

#include <CLI/CLI.hpp>

#include <string>

namespace tessera::cli {

class HelpFormatter final : public CLI::Formatter {
public:
    explicit HelpFormatter(std::string program) : mProgram(std::move(program)) {}

    std::string make_usage(const CLI::App* app, std::string name) const override;
    std::string make_description(const CLI::App* app) const override;
    std::string make_group(std::string group, bool positional, std::vector<const CLI::Option*> opts) const override;
    std::string make_option(const CLI::Option* opt, bool positional) const override;
    std::string make_option_opts(const CLI::Option* opt) const override;
    std::string make_option_name(const CLI::Option* opt, bool positional) const override;

private:
    std::string mProgram;
};

/// `text` wrapped to `width` columns, every line after the first indented
/// by `indent` spaces (the first continues where the caller's column is).
std::string wrapText(const std::string& text, size_t firstColumn, size_t indent, size_t width);

} // namespace tessera::cli
