#include "HelpFormatter.h"

#include <sstream>

namespace tessera::cli {
namespace {

constexpr size_t kMargin = 24; // where descriptions start
constexpr size_t kWidth = 79;

} // namespace

std::string wrapText(const std::string& text, size_t firstColumn, size_t indent, size_t width) {
    std::istringstream words(text);
    std::string word, out;
    size_t column = firstColumn;
    bool lineEmpty = true;
    while (words >> word) {
        if (!lineEmpty && column + 1 + word.size() > width) {
            out += '\n' + std::string(indent, ' ');
            column = indent;
            lineEmpty = true;
        }
        if (!lineEmpty) {
            out += ' ';
            ++column;
        }
        out += word;
        column += word.size();
        lineEmpty = false;
    }
    return out;
}

// CLI11 prints the description before the usage line; the usage line
// comes first in every Unix tool, so the description prints both.
std::string HelpFormatter::make_usage(const CLI::App*, std::string) const { return {}; }

std::string HelpFormatter::make_description(const CLI::App* app) const {
    const std::string usage = "usage: " + mProgram + " [options]\n\n";
    const std::string description = app->get_description();
    return description.empty() ? usage : usage + wrapText(description, 0, 0, kWidth) + "\n\n";
}

std::string HelpFormatter::make_group(std::string group, bool positional, std::vector<const CLI::Option*> opts) const {
    std::string out = group + ":\n";
    for (const CLI::Option* opt : opts) out += make_option(opt, positional);
    return out; // CLI11 puts the blank line between groups
}

std::string HelpFormatter::make_option_opts(const CLI::Option* opt) const {
    // The argument's name only (N, FILE, ...); ranges and defaults are in
    // the description, in words, where they read better than CLI11's forms.
    return opt->get_expected_max() == 0 ? std::string() : " " + opt->get_type_name();
}

std::string HelpFormatter::make_option_name(const CLI::Option* opt, bool positional) const {
    // "--no-mips{false}" declares the value a flag sets; users type "--no-mips".
    std::string name = CLI::Formatter::make_option_name(opt, positional);
    for (size_t open = name.find('{'); open != std::string::npos; open = name.find('{'))
        name.erase(open, name.find('}', open) - open + 1);
    return name;
}

std::string HelpFormatter::make_option(const CLI::Option* opt, bool positional) const {
    std::string line = "  " + make_option_name(opt, positional) + make_option_opts(opt);
    if (line.size() + 1 >= kMargin) line += '\n' + std::string(kMargin, ' ');
    else line += std::string(kMargin - line.size(), ' ');
    return line + wrapText(opt->get_description(), kMargin, kMargin, kWidth) + "\n";
}

} // namespace tessera::cli
