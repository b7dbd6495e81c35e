#include "tessera/cli/Validators.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace tessera::cli {

std::string formatNumber(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

std::string listChoices(const std::vector<std::string>& choices) {
    std::string out;
    for (size_t i = 0; i < choices.size(); ++i)
        out += (i == 0 ? "" : i + 1 == choices.size() ? " or " : ", ") + choices[i];
    return out;
}

CLI::Validator count(uint64_t lo, uint64_t hi) {
    const std::string expects =
        "expects a whole number from " + std::to_string(lo) + " to " + std::to_string(hi);
    return CLI::Validator(
        [lo, hi, expects](std::string& text) -> std::string {
            uint64_t value = 0;
            auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
            if (text.empty() || ec != std::errc() || end != text.data() + text.size() || value < lo || value > hi)
                return expects + ", got \"" + text + "\"";
            return {};
        },
        "", "count");
}

CLI::Validator number(double lo, double hi) {
    const std::string expects = "expects a number from " + formatNumber(lo) + " to " + formatNumber(hi);
    return CLI::Validator(
        [lo, hi, expects](std::string& text) -> std::string {
            // strtod, not from_chars: GCC 12's from_chars for double is fine,
            // but strtod is what the old parser accepted ("1e3", "0x10").
            char* end = nullptr;
            const double v = std::strtod(text.c_str(), &end);
            if (text.empty() || *end != '\0' || !std::isfinite(v) || v < lo || v > hi)
                return expects + ", got \"" + text + "\"";
            return {};
        },
        "", "number");
}

CLI::Validator oneOf(std::vector<std::string> choices) {
    return CLI::Validator(
        [choices](std::string& text) -> std::string {
            for (const auto& c : choices)
                if (text == c) return {};
            return "expects " + listChoices(choices) + ", got \"" + text + "\"";
        },
        "", "choice");
}

CLI::Validator nonEmpty() {
    return CLI::Validator([](std::string& text) -> std::string { return text.empty() ? "needs a file name" : ""; },
                          "", "path");
}

} // namespace tessera::cli
