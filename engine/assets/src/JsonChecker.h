#pragma once
// JsonChecker: typed, range-checked access to glTF JSON properties. Every
// accessor takes the object, its JSON pointer and the key; a missing required
// property, a wrong type, a value out of range or an index that does not
// resolve throws GltfError naming the pointer.

#include "GltfError.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace tessera::assets {

using Json = nlohmann::json;

class JsonChecker {
public:
    explicit JsonChecker(const Json& root) : mRoot(root) {}

    const Json& root() const { return mRoot; }
    /// Number of elements of a root collection ("accessors"), 0 when absent.
    size_t count(const char* collection) const;

    /// The value must be a JSON object.
    const Json& asObject(const Json& value, const std::string& ptr) const;
    const Json* optObject(const Json& o, const std::string& ptr, const char* key) const;
    const Json& reqObject(const Json& o, const std::string& ptr, const char* key) const;
    /// Arrays must hold at least `minItems` elements (glTF forbids empty arrays).
    const Json* optArray(const Json& o, const std::string& ptr, const char* key, size_t minItems = 1) const;
    const Json& reqArray(const Json& o, const std::string& ptr, const char* key, size_t minItems = 1) const;

    std::optional<int64_t> optInt(const Json& o, const std::string& ptr, const char* key,
                                  int64_t lo = 0, int64_t hi = std::numeric_limits<int64_t>::max()) const;
    int64_t reqInt(const Json& o, const std::string& ptr, const char* key,
                   int64_t lo = 0, int64_t hi = std::numeric_limits<int64_t>::max()) const;
    /// A finite number in [lo, hi] (lo excluded when loExclusive).
    std::optional<double> optNumber(const Json& o, const std::string& ptr, const char* key,
                                    double lo = -std::numeric_limits<double>::max(),
                                    double hi = std::numeric_limits<double>::max(), bool loExclusive = false) const;
    double reqNumber(const Json& o, const std::string& ptr, const char* key,
                     double lo = -std::numeric_limits<double>::max(),
                     double hi = std::numeric_limits<double>::max(), bool loExclusive = false) const;
    std::optional<std::string> optString(const Json& o, const std::string& ptr, const char* key) const;
    std::string reqString(const Json& o, const std::string& ptr, const char* key) const;
    std::optional<bool> optBool(const Json& o, const std::string& ptr, const char* key) const;
    /// A string property restricted to `allowed`.
    std::optional<std::string> optEnum(const Json& o, const std::string& ptr, const char* key,
                                       const std::vector<std::string>& allowed) const;
    /// An integer property restricted to `allowed`.
    std::optional<int64_t> optIntEnum(const Json& o, const std::string& ptr, const char* key,
                                      const std::vector<int64_t>& allowed) const;

    /// An index into the root collection `collection`.
    std::optional<size_t> optIndex(const Json& o, const std::string& ptr, const char* key, const char* collection) const;
    size_t reqIndex(const Json& o, const std::string& ptr, const char* key, const char* collection) const;
    /// Checks that `value` (at `ptr`) is an integer index below `size`.
    size_t checkIndex(const Json& value, const std::string& ptr, size_t size) const;
    /// A non-empty array of unique indices into `collection`.
    std::vector<size_t> indexArray(const Json& o, const std::string& ptr, const char* key, const char* collection,
                                   bool required) const;
    /// An array of exactly `n` finite numbers in [lo, hi] (n = 0: any length >= 1).
    std::optional<std::vector<double>> optNumbers(const Json& o, const std::string& ptr, const char* key, size_t n,
                                                  double lo = -std::numeric_limits<double>::max(),
                                                  double hi = std::numeric_limits<double>::max()) const;

    /// Property must be absent unless `dependency` is present (UNSATISFIED_DEPENDENCY).
    void requireWith(const Json& o, const std::string& ptr, const char* key, const char* dependency) const;

private:
    const Json& mRoot;
};

/// "ptr/key" with JSON pointer escaping of the key.
std::string childPointer(const std::string& ptr, const std::string& key);
std::string childPointer(const std::string& ptr, size_t index);

} // namespace tessera::assets
