#pragma once
/// @file JsonFile.h
/// The tests' reading of the demo's JSON outputs (benchmark reports, traces,
/// `--crowd-tiers`, `--bench` records): nlohmann::json parses, and these few
/// lookups turn a missing or mistyped member into nullopt or null, so a test
/// fails with its own message instead of an exception.

#include "TestFiles.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>
#include <string>

namespace tessera::test {

/// Reads and parses `path`; false, with nlohmann's reason in `error` (the
/// caller names the file), when the file is missing or is not one JSON value.
inline bool readJsonFile(const std::filesystem::path& path, nlohmann::json& out, std::string& error) {
    try {
        out = nlohmann::json::parse(readTextFile(path));
        return true;
    } catch (const nlohmann::json::exception& e) {
        error = e.what();
        out = nullptr;
        return false;
    }
}

/// The member `key` of `object`, or null when there is none (or `object` is
/// not an object).
inline const nlohmann::json* memberOf(const nlohmann::json& object, const std::string& key) {
    if (!object.is_object()) return nullptr;
    auto it = object.find(key);
    return it == object.end() ? nullptr : &*it;
}

/// The number at `key`, if `object` has a number there.
inline std::optional<double> numberAt(const nlohmann::json& object, const std::string& key) {
    const nlohmann::json* v = memberOf(object, key);
    if (!v || !v->is_number()) return std::nullopt;
    return v->get<double>();
}

/// The string at `key`, if `object` has a string there.
inline std::optional<std::string> stringAt(const nlohmann::json& object, const std::string& key) {
    const nlohmann::json* v = memberOf(object, key);
    if (!v || !v->is_string()) return std::nullopt;
    return v->get<std::string>();
}

} // namespace tessera::test
