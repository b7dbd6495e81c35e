#include "tessera/cli/Validators.h"

#include "tessera/cli/NumberList.h"

#include <cstdio>

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
    const ListForm form{"", "a whole number from " + std::to_string(lo) + " to " + std::to_string(hi), {}, 1, 1, ',',
                        double(lo), double(hi)};
    return CLI::Validator(
        [form](std::string& text) -> std::string {
            auto value = parseNumber<uint64_t>(text, form);
            if (!value) return value.error().message;
            // CLI11 reads integers with strtoull's base 0 ("010" is eight):
            // it gets the value read here, in plain decimal.
            text = std::to_string(value.value());
            return {};
        },
        "", "count");
}

CLI::Validator number(double lo, double hi) {
    const ListForm form{"", "a number from " + formatNumber(lo) + " to " + formatNumber(hi), {}, 1, 1, ',', lo, hi};
    return CLI::Validator(
        [form](std::string& text) -> std::string {
            if (auto value = parseNumber<double>(text, form); !value) return value.error().message;
            // CLI11 converts the text itself (strtold, into the option's
            // type); it gets the number without what the rules let around it.
            text = std::string(withoutPlus(splitList(text).front()));
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
