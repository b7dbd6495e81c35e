#pragma once
/// @file BenchText.h
/// Small writers the benchmark reports share: a printf-formatted table line,
/// and JSON numbers in fixed notation (no exponents for people and for
/// hand-written readers).

#include "tessera/core/JsonWriter.h"

#include <cstdio>
#include <initializer_list>
#include <string>
#include <string_view>

namespace tessera::runtime {

/// `pattern` formatted with `args` (std::snprintf), up to 319 characters.
std::string format(const char* pattern, auto... args) {
    char line[320];
    std::snprintf(line, sizeof line, pattern, args...);
    return line;
}

/// key(name), then `value` rounded to at most `decimals` decimals.
inline void fixed(JsonWriter& json, std::string_view name, double value, int decimals) {
    json.key(name);
    json.valueFixed(value, decimals);
}

/// One named number of an object written by fixedObject.
struct FixedField {
    const char* name;
    double value;
    int decimals;
};

/// key(name), then an object of `fields` (fixed() each).
inline void fixedObject(JsonWriter& json, std::string_view name, std::initializer_list<FixedField> fields) {
    json.key(name);
    json.beginObject();
    for (const FixedField& field : fields) fixed(json, field.name, field.value, field.decimals);
    json.endObject();
}

/// Opens a benchmark's JSON document: an object with "format" and "version".
inline void beginBenchDocument(JsonWriter& json, std::string_view format, int version) {
    json.beginObject();
    json.keyValue("format", format);
    json.keyValue("version", version);
}

} // namespace tessera::runtime
