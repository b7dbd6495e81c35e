#include "tessera/cli/NumberList.h"

#include "tessera/cli/Validators.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <system_error>
#include <type_traits>

namespace tessera::cli {
namespace {

std::string quoted(std::string_view s) { return "\"" + std::string(s) + "\""; }

std::string_view trim(std::string_view s) {
    constexpr std::string_view kSpace = " \t";
    const size_t first = s.find_first_not_of(kSpace);
    if (first == std::string_view::npos) return {};
    return s.substr(first, s.find_last_not_of(kSpace) - first + 1);
}

/// Why an item is not a good number; None when it is one.
enum class Fault { None, Missing, NotANumber, NotFinite, OutOfRange, OutsideForm };

const char* describe(Fault fault) {
    switch (fault) {
    case Fault::NotANumber: return " is not a number";
    case Fault::NotFinite: return " is not a finite number";
    case Fault::OutOfRange: return " is out of range";
    default: return "";
    }
}

template <class T>
Fault readItem(std::string_view item, const ListForm& form, T& value) {
    if (item.empty()) return Fault::Missing;
    const std::string_view digits = withoutPlus(item);
    // from_chars reads no sign into an unsigned T and no "0x" prefix, and
    // depends on no locale: "1,5" is never one and a half.
    auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (ec == std::errc::result_out_of_range) return Fault::OutOfRange;
    if (ec != std::errc() || end != digits.data() + digits.size()) return Fault::NotANumber;
    // from_chars reads "nan" and "inf", which would poison every matrix.
    if constexpr (std::is_floating_point_v<T>)
        if (!std::isfinite(value)) return Fault::NotFinite;
    if (double(value) < form.lo || double(value) > form.hi) return Fault::OutsideForm;
    return Fault::None;
}

/// The message for `fault` in item `index` of `text`.
Error itemError(const ListForm& form, std::string_view text, size_t index, std::string_view item, Fault fault) {
    if (index >= form.itemNames.size()) return expectedError(form, item.empty() ? text : item);
    const std::string& field = form.itemNames[index];
    if (fault == Fault::Missing) {
        std::string names;
        for (const std::string& n : form.itemNames) names += (names.empty() ? "" : std::string(1, form.separator)) + n;
        return fail(form.name, ": ", field, " is missing in ", quoted(text), " (expects ", names, ")");
    }
    if (fault == Fault::OutsideForm)
        return fail(form.name, ": ", field, " = ", quoted(item), " is not in [", formatNumber(form.lo), ", ",
                    formatNumber(form.hi), "]");
    return fail(form.name, ": ", field, " = ", quoted(item), describe(fault));
}

} // namespace

std::string_view withoutPlus(std::string_view item) {
    // from_chars rejects a leading '+', which people type ("+10"); allow one,
    // but not "+-1" or a bare "+".
    if (item.size() > 1 && item[0] == '+' && item[1] != '-' && item[1] != '+') item.remove_prefix(1);
    return item;
}

std::vector<std::string_view> splitList(std::string_view text, char separator) {
    std::vector<std::string_view> items;
    if (text.empty()) return items;
    for (size_t start = 0;;) {
        const size_t end = text.find(separator, start);
        items.push_back(trim(text.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start)));
        if (end == std::string_view::npos) return items;
        start = end + 1;
    }
}

Error expectedError(const ListForm& form, std::string_view text) {
    return fail(form.name, form.name.empty() ? "" : " ", "expects ", form.expects, ", got ", quoted(text));
}

template <class T>
Result<std::vector<T>> parseNumberList(std::string_view text, const ListForm& form) {
    const std::vector<std::string_view> items = splitList(text, form.separator);
    if (items.size() < form.minCount || items.size() > form.maxCount) return expectedError(form, text);
    std::vector<T> values(items.size());
    for (size_t i = 0; i < items.size(); ++i)
        if (Fault fault = readItem(items[i], form, values[i]); fault != Fault::None)
            return itemError(form, text, i, items[i], fault);
    return values;
}

template <class T>
Result<T> parseNumber(std::string_view text, const ListForm& form) {
    ListForm one = form;
    one.minCount = one.maxCount = 1;
    auto values = parseNumberList<T>(text, one);
    if (!values) return values.error();
    return values.value().front();
}

template Result<std::vector<uint32_t>> parseNumberList<uint32_t>(std::string_view, const ListForm&);
template Result<std::vector<uint64_t>> parseNumberList<uint64_t>(std::string_view, const ListForm&);
template Result<std::vector<float>> parseNumberList<float>(std::string_view, const ListForm&);
template Result<std::vector<double>> parseNumberList<double>(std::string_view, const ListForm&);
template Result<uint32_t> parseNumber<uint32_t>(std::string_view, const ListForm&);
template Result<uint64_t> parseNumber<uint64_t>(std::string_view, const ListForm&);
template Result<float> parseNumber<float>(std::string_view, const ListForm&);
template Result<double> parseNumber<double>(std::string_view, const ListForm&);

} // namespace tessera::cli
