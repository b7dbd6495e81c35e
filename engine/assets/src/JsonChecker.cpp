#include "JsonChecker.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace tessera::assets {

std::string childPointer(const std::string& ptr, const std::string& key) {
    std::string escaped;
    for (char c : key) {
        if (c == '~') escaped += "~0";
        else if (c == '/') escaped += "~1";
        else escaped += c;
    }
    return ptr + "/" + escaped;
}

std::string childPointer(const std::string& ptr, size_t index) { return ptr + "/" + std::to_string(index); }

size_t JsonChecker::count(const char* collection) const {
    auto it = mRoot.find(collection);
    return it != mRoot.end() && it->is_array() ? it->size() : 0;
}

const Json& JsonChecker::asObject(const Json& value, const std::string& ptr) const {
    if (!value.is_object()) raise(ptr, "type mismatch, " + value.dump().substr(0, 40) + " is not an object");
    return value;
}

const Json* JsonChecker::optObject(const Json& o, const std::string& ptr, const char* key) const {
    auto it = o.find(key);
    if (it == o.end()) return nullptr;
    return &asObject(*it, childPointer(ptr, key));
}

const Json& JsonChecker::reqObject(const Json& o, const std::string& ptr, const char* key) const {
    const Json* v = optObject(o, ptr, key);
    if (!v) raise(ptr, std::string("required property '") + key + "' is missing");
    return *v;
}

const Json* JsonChecker::optArray(const Json& o, const std::string& ptr, const char* key, size_t minItems) const {
    auto it = o.find(key);
    if (it == o.end()) return nullptr;
    std::string p = childPointer(ptr, key);
    if (!it->is_array()) raise(p, "type mismatch, expected an array");
    if (it->size() < minItems) raise(p, it->empty() ? "array cannot be empty" : "array is too short");
    return &*it;
}

const Json& JsonChecker::reqArray(const Json& o, const std::string& ptr, const char* key, size_t minItems) const {
    const Json* v = optArray(o, ptr, key, minItems);
    if (!v) raise(ptr, std::string("required property '") + key + "' is missing");
    return *v;
}

std::optional<int64_t> JsonChecker::optInt(const Json& o, const std::string& ptr, const char* key, int64_t lo,
                                           int64_t hi) const {
    auto it = o.find(key);
    if (it == o.end()) return std::nullopt;
    std::string p = childPointer(ptr, key);
    int64_t v = 0;
    if (it->is_number_unsigned()) {
        uint64_t u = it->get<uint64_t>();
        if (u > static_cast<uint64_t>(std::numeric_limits<int64_t>::max())) raise(p, "value out of range");
        v = static_cast<int64_t>(u);
    } else if (it->is_number_integer()) {
        v = it->get<int64_t>();
    } else if (it->is_number_float() && std::isfinite(it->get<double>()) &&
               std::floor(it->get<double>()) == it->get<double>() && std::fabs(it->get<double>()) < 9e15) {
        v = static_cast<int64_t>(it->get<double>());
    } else {
        raise(p, "type mismatch, expected an integer");
    }
    if (v < lo || v > hi) raise(p, "value " + std::to_string(v) + " is out of range");
    return v;
}

int64_t JsonChecker::reqInt(const Json& o, const std::string& ptr, const char* key, int64_t lo, int64_t hi) const {
    auto v = optInt(o, ptr, key, lo, hi);
    if (!v) raise(ptr, std::string("required property '") + key + "' is missing");
    return *v;
}

static double checkedNumber(const Json& v, const std::string& p, double lo, double hi, bool loExclusive) {
    if (!v.is_number()) raise(p, "type mismatch, expected a number");
    double d = v.get<double>();
    if (!std::isfinite(d) || d < lo || d > hi || (loExclusive && d == lo))
        raise(p, "value " + v.dump() + " is out of range");
    return d;
}

std::optional<double> JsonChecker::optNumber(const Json& o, const std::string& ptr, const char* key, double lo,
                                             double hi, bool loExclusive) const {
    auto it = o.find(key);
    if (it == o.end()) return std::nullopt;
    return checkedNumber(*it, childPointer(ptr, key), lo, hi, loExclusive);
}

double JsonChecker::reqNumber(const Json& o, const std::string& ptr, const char* key, double lo, double hi,
                              bool loExclusive) const {
    auto v = optNumber(o, ptr, key, lo, hi, loExclusive);
    if (!v) raise(ptr, std::string("required property '") + key + "' is missing");
    return *v;
}

std::optional<std::string> JsonChecker::optString(const Json& o, const std::string& ptr, const char* key) const {
    auto it = o.find(key);
    if (it == o.end()) return std::nullopt;
    if (!it->is_string()) raise(childPointer(ptr, key), "type mismatch, expected a string");
    return it->get<std::string>();
}

std::string JsonChecker::reqString(const Json& o, const std::string& ptr, const char* key) const {
    auto v = optString(o, ptr, key);
    if (!v) raise(ptr, std::string("required property '") + key + "' is missing");
    return *v;
}

std::optional<bool> JsonChecker::optBool(const Json& o, const std::string& ptr, const char* key) const {
    auto it = o.find(key);
    if (it == o.end()) return std::nullopt;
    if (!it->is_boolean()) raise(childPointer(ptr, key), "type mismatch, expected a boolean");
    return it->get<bool>();
}

std::optional<std::string> JsonChecker::optEnum(const Json& o, const std::string& ptr, const char* key,
                                                const std::vector<std::string>& allowed) const {
    auto v = optString(o, ptr, key);
    if (v && std::find(allowed.begin(), allowed.end(), *v) == allowed.end())
        raise(childPointer(ptr, key), "invalid value '" + *v + "'");
    return v;
}

std::optional<int64_t> JsonChecker::optIntEnum(const Json& o, const std::string& ptr, const char* key,
                                               const std::vector<int64_t>& allowed) const {
    auto v = optInt(o, ptr, key, std::numeric_limits<int64_t>::min());
    if (v && std::find(allowed.begin(), allowed.end(), *v) == allowed.end())
        raise(childPointer(ptr, key), "invalid value " + std::to_string(*v));
    return v;
}

size_t JsonChecker::checkIndex(const Json& value, const std::string& ptr, size_t size) const {
    int64_t v = 0;
    if (value.is_number_unsigned()) v = static_cast<int64_t>(std::min<uint64_t>(value.get<uint64_t>(), 1ull << 62));
    else if (value.is_number_integer()) v = value.get<int64_t>();
    else if (value.is_number_float() && std::floor(value.get<double>()) == value.get<double>() &&
             std::fabs(value.get<double>()) < 1e15)
        v = static_cast<int64_t>(value.get<double>());  // "1.0" is an integer to JSON Schema
    else raise(ptr, "type mismatch, expected an index");
    if (v < 0 || static_cast<uint64_t>(v) >= size) raise(ptr, "unresolved reference " + value.dump());
    return static_cast<size_t>(v);
}

std::optional<size_t> JsonChecker::optIndex(const Json& o, const std::string& ptr, const char* key,
                                            const char* collection) const {
    auto it = o.find(key);
    if (it == o.end()) return std::nullopt;
    return checkIndex(*it, childPointer(ptr, key), count(collection));
}

size_t JsonChecker::reqIndex(const Json& o, const std::string& ptr, const char* key, const char* collection) const {
    auto v = optIndex(o, ptr, key, collection);
    if (!v) raise(ptr, std::string("required property '") + key + "' is missing");
    return *v;
}

std::vector<size_t> JsonChecker::indexArray(const Json& o, const std::string& ptr, const char* key,
                                            const char* collection, bool required) const {
    const Json* a = required ? &reqArray(o, ptr, key) : optArray(o, ptr, key);
    std::vector<size_t> out;
    if (!a) return out;
    std::set<size_t> seen;
    std::string p = childPointer(ptr, key);
    for (size_t i = 0; i < a->size(); ++i) {
        size_t idx = checkIndex((*a)[i], childPointer(p, i), count(collection));
        if (!seen.insert(idx).second) raise(childPointer(p, i), "duplicate element");
        out.push_back(idx);
    }
    return out;
}

std::optional<std::vector<double>> JsonChecker::optNumbers(const Json& o, const std::string& ptr, const char* key,
                                                           size_t n, double lo, double hi) const {
    const Json* a = optArray(o, ptr, key);
    if (!a) return std::nullopt;
    std::string p = childPointer(ptr, key);
    if (n != 0 && a->size() != n) raise(p, "array must have " + std::to_string(n) + " elements");
    std::vector<double> out;
    for (size_t i = 0; i < a->size(); ++i) out.push_back(checkedNumber((*a)[i], childPointer(p, i), lo, hi, false));
    return out;
}

void JsonChecker::requireWith(const Json& o, const std::string& ptr, const char* key, const char* dependency) const {
    if (o.contains(key) && !o.contains(dependency))
        raise(childPointer(ptr, key), std::string("dependency failed, '") + dependency + "' must be defined");
}

} // namespace tessera::assets
