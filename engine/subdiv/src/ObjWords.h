#pragma once
/// @file ObjWords.h
/// The lexical layer of the .obj reader (ObjShape.cpp): splitting a line
/// into words and reading numbers and element references from them. Free
/// functions, no state; every one is total (any bytes in, no crash, no
/// exception, no locale).

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tessera::subdiv::obj {

/// Splits `line` at ASCII whitespace into `words` (cleared first; the views
/// point into `line`).
void splitWords(std::string_view line, std::vector<std::string_view>& words);

/// A whole word as a decimal number ("1", "-0.5", "2.5e-3", "+1", "inf",
/// "nan"): std::from_chars, so "1,5" is malformed in every locale.
/// Non-finite values parse (the caller says whether they are allowed);
/// nullopt for a malformed word or one outside double's range.
std::optional<double> parseNumber(std::string_view word);

/// A whole word as a decimal integer; nullopt when malformed or outside
/// int64_t.
std::optional<int64_t> parseInteger(std::string_view word);

/// A finite double as a finite float; nullopt for NaN, infinity or a value
/// beyond float's range (which would round to infinity).
std::optional<float> toFiniteFloat(double value);

/// An .obj reference to the `count` elements defined so far (1-based, or
/// negative: -1 is the last one) as a 0-based index; nullopt for 0 and for
/// anything outside 1..count or -count..-1.
std::optional<uint32_t> resolveReference(int64_t reference, size_t count);

/// `word` for a one-line message: in quotes, at most 32 characters, control
/// and non-ASCII bytes shown as '?', so hostile bytes cannot break the line.
std::string quotedWord(std::string_view word);

} // namespace tessera::subdiv::obj
