#include "ObjWords.h"

#include <charconv>
#include <cmath>
#include <limits>
#include <system_error>

namespace tessera::subdiv::obj {

namespace {

bool isSpace(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f';
}

/// from_chars rejects a leading '+', which some exporters write; accept one
/// '+' before a digit or a point (not "+-1" or "++1").
std::string_view withoutPlus(std::string_view word) {
    if (word.size() >= 2 && word[0] == '+' && word[1] != '-' && word[1] != '+') return word.substr(1);
    return word;
}

/// Parses all of `word` as T; nullopt unless every character was used.
template <class T> std::optional<T> parseWhole(std::string_view word) {
    word = withoutPlus(word);
    T value{};
    const char* end = word.data() + word.size();
    const auto [ptr, ec] = std::from_chars(word.data(), end, value);
    if (ec != std::errc() || ptr != end) return std::nullopt;
    return value;
}

} // namespace

void splitWords(std::string_view line, std::vector<std::string_view>& words) {
    words.clear();
    size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && isSpace(line[i])) ++i;
        const size_t start = i;
        while (i < line.size() && !isSpace(line[i])) ++i;
        if (i > start) words.push_back(line.substr(start, i - start));
    }
}

std::optional<double> parseNumber(std::string_view word) {
    if (word.empty()) return std::nullopt;
    return parseWhole<double>(word);
}

std::optional<int64_t> parseInteger(std::string_view word) {
    if (word.empty()) return std::nullopt;
    return parseWhole<int64_t>(word);
}

std::optional<float> toFiniteFloat(double value) {
    if (!std::isfinite(value) || std::fabs(value) > double(std::numeric_limits<float>::max())) return std::nullopt;
    return float(value);
}

std::optional<uint32_t> resolveReference(int64_t reference, size_t count) {
    // Compare in int64_t: count is at most the number of lines read, far
    // below 2^63, and reference may be any int64_t (no negation overflow:
    // reference < 0 is only ever added to).
    const int64_t n = int64_t(count);
    int64_t index = -1;
    if (reference > 0 && reference <= n)
        index = reference - 1;
    else if (reference < 0 && reference >= -n)
        index = n + reference;
    if (index < 0 || index > int64_t(std::numeric_limits<uint32_t>::max())) return std::nullopt;
    return uint32_t(index);
}

std::string quotedWord(std::string_view word) {
    constexpr size_t kMaxShown = 32;
    std::string text = "'";
    for (size_t i = 0; i < word.size() && i < kMaxShown; ++i) {
        const unsigned char c = static_cast<unsigned char>(word[i]);
        text += (c >= 0x20 && c < 0x7f) ? char(c) : '?';
    }
    if (word.size() > kMaxShown) text += "...";
    text += "'";
    return text;
}

} // namespace tessera::subdiv::obj
