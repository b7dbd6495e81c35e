#pragma once
/// @file NumberList.h
/// The one reader of values written as lists: a position and heading
/// ("x,y,z,yaw,pitch"), crowd sizes ("1000,10000,65000"), a sweep ("A:B"), a
/// single number (a list of one), names ("tessellation,geometry"). Every flag
/// and every input that takes a list reads it here, by one set of rules:
///
/// - items are separated by one character (',' unless the form says
///   otherwise); spaces and tabs around an item are ignored; between two
///   separators, or after the last, there is an (empty) item;
/// - a number is decimal as std::from_chars reads it, independent of the
///   locale ("1.5", "-2", "3e2"), with at most one leading '+' ("+10"); hex
///   ("0x10"), "inf" and "nan" are not numbers a user means;
/// - a whole number (an unsigned T) has no sign, point or exponent;
/// - a real number (a floating-point T) is finite and fits T;
/// - every number lies in the form's range [lo, hi].
///
/// And one wording for what breaks them (the examples are the demo's):
/// - a list of the wrong length, and a bad item of a list whose items have
///   no names: `<name> expects <expects>, got "<text or item>"`
///   (`--subdiv-level expects a number from 1 to 64, got "99"`);
/// - a bad item of a list whose items are named:
///   `--camera: y = "abc" is not a number`, `... is not a finite number`,
///   `... is out of range` (beyond T), `... is not in [lo, hi]`, and for an
///   empty one `--camera: z is missing in "1,2,,4,5" (expects x,y,z,yaw,pitch)`.

#include "tessera/core/Result.h"

#include <cstddef>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace tessera::cli {

/// How a list of numbers is written and which values it takes.
struct ListForm {
    /// The flag or input the list belongs to ("--camera"), at the head of
    /// every message; may be empty (a CLI11 validator's message, which CLI11
    /// prefixes with the flag itself).
    std::string name;
    /// What a good value is, in words: `<name> expects <expects>, got "..."`
    /// ("x,y,z,yaw,pitch (5 numbers)", "a number from 1 to 64").
    std::string expects;
    /// The items' names when each position has its own ("x", "y", "z", ...):
    /// a bad item is then named in its message. Empty: items are alike.
    std::vector<std::string> itemNames = {};
    size_t minCount = 1;
    size_t maxCount = 1;
    char separator = ',';
    double lo = -std::numeric_limits<double>::infinity();
    double hi = std::numeric_limits<double>::infinity();
};

/// The items of `text` between `separator`s, each without the spaces and
/// tabs around it. "" has no items; "a," has two, the second empty.
std::vector<std::string_view> splitList(std::string_view text, char separator = ',');

/// Reads `text` as a list of T by the rules above. T is uint32_t, uint64_t,
/// float or double.
template <class T>
Result<std::vector<T>> parseNumberList(std::string_view text, const ListForm& form);

/// The one number of `text` (a list of one), by the same rules.
template <class T>
Result<T> parseNumber(std::string_view text, const ListForm& form);

/// `<name> expects <expects>, got "<text>"`: the message for a value the
/// caller refuses after reading it (a crater's radius of 0), in the same
/// words as the reader's own.
Error expectedError(const ListForm& form, std::string_view text);

/// An item as a number's reader sees it: without the one leading '+' the
/// rules allow, so "+10" reads as "10" (and "+", "+-1" stay as they are).
std::string_view withoutPlus(std::string_view item);

} // namespace tessera::cli
