#pragma once
/// @file JsonReader.h
/// A small JSON reader for the tests that check the demo's JSON outputs
/// (benchmark reports, `--bench terrain` records): objects, arrays, strings,
/// numbers, true, false and null. Strings keep \uXXXX escapes below 0x80 and
/// replace other code points with '?', which is enough for the demo's
/// outputs. Not for untrusted input (recursion depth is not limited).

#include <cctype>
#include <cstdlib>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace tessera::test {

struct JsonValue {
    enum class Type { Null, Bool, Number, String, Array, Object };
    Type type = Type::Null;
    bool boolean = false;
    double number = 0.0;
    std::string string;
    std::vector<JsonValue> array;
    std::map<std::string, JsonValue> object;

    bool isObject() const { return type == Type::Object; }
    bool isArray() const { return type == Type::Array; }
    bool isNumber() const { return type == Type::Number; }
    bool isString() const { return type == Type::String; }
    bool isNull() const { return type == Type::Null; }

    /// The member `key` of an object, or null when there is none (or this is
    /// not an object).
    const JsonValue* find(const std::string& key) const {
        if (type != Type::Object) return nullptr;
        auto it = object.find(key);
        return it == object.end() ? nullptr : &it->second;
    }
    /// The number at `key`, if this is an object with a number there.
    std::optional<double> numberAt(const std::string& key) const {
        const JsonValue* v = find(key);
        if (!v || !v->isNumber()) return std::nullopt;
        return v->number;
    }
    /// The string at `key`, if this is an object with a string there.
    std::optional<std::string> stringAt(const std::string& key) const {
        const JsonValue* v = find(key);
        if (!v || !v->isString()) return std::nullopt;
        return v->string;
    }
};

namespace detail {

class JsonParser {
public:
    explicit JsonParser(const std::string& text) : mText(text) {}

    bool parseDocument(JsonValue& out, std::string& error) {
        skipSpace();
        if (!parseValue(out)) {
            error = mError.empty() ? "bad JSON at offset " + std::to_string(mAt) : mError;
            return false;
        }
        skipSpace();
        if (mAt != mText.size()) {
            error = "text after the JSON value at offset " + std::to_string(mAt);
            return false;
        }
        return true;
    }

private:
    bool failAt(const std::string& what) {
        if (mError.empty()) mError = what + " at offset " + std::to_string(mAt);
        return false;
    }
    void skipSpace() {
        while (mAt < mText.size() && std::isspace(static_cast<unsigned char>(mText[mAt]))) ++mAt;
    }
    bool literal(const char* word) {
        const std::string w(word);
        if (mText.compare(mAt, w.size(), w) != 0) return false;
        mAt += w.size();
        return true;
    }
    bool parseString(std::string& out) {
        if (mAt >= mText.size() || mText[mAt] != '"') return failAt("expected a string");
        out.clear();
        for (++mAt; mAt < mText.size() && mText[mAt] != '"'; ++mAt) {
            char c = mText[mAt];
            if (c != '\\') {
                out += c;
                continue;
            }
            if (++mAt >= mText.size()) break;
            switch (mText[mAt]) {
            case 'n':
                out += '\n';
                break;
            case 't':
                out += '\t';
                break;
            case 'r':
                out += '\r';
                break;
            case 'b':
                out += '\b';
                break;
            case 'f':
                out += '\f';
                break;
            case 'u': {
                if (mAt + 4 >= mText.size()) return failAt("short \\u escape");
                const unsigned long code = std::strtoul(mText.substr(mAt + 1, 4).c_str(), nullptr, 16);
                out += code < 0x80 ? char(code) : '?';
                mAt += 4;
                break;
            }
            default:
                out += mText[mAt];
                break; // \" \\ \/
            }
        }
        if (mAt >= mText.size()) return failAt("unterminated string");
        ++mAt;
        return true;
    }
    bool parseValue(JsonValue& out) {
        skipSpace();
        if (mAt >= mText.size()) return failAt("expected a value");
        const char c = mText[mAt];
        if (c == '{') {
            out.type = JsonValue::Type::Object;
            ++mAt;
            skipSpace();
            if (mAt < mText.size() && mText[mAt] == '}') return ++mAt, true;
            while (true) {
                skipSpace();
                std::string key;
                if (!parseString(key)) return false;
                skipSpace();
                if (mAt >= mText.size() || mText[mAt] != ':') return failAt("expected ':'");
                ++mAt;
                if (!parseValue(out.object[key])) return false;
                skipSpace();
                if (mAt < mText.size() && mText[mAt] == ',') {
                    ++mAt;
                    continue;
                }
                if (mAt < mText.size() && mText[mAt] == '}') return ++mAt, true;
                return failAt("expected ',' or '}'");
            }
        }
        if (c == '[') {
            out.type = JsonValue::Type::Array;
            ++mAt;
            skipSpace();
            if (mAt < mText.size() && mText[mAt] == ']') return ++mAt, true;
            while (true) {
                out.array.emplace_back();
                if (!parseValue(out.array.back())) return false;
                skipSpace();
                if (mAt < mText.size() && mText[mAt] == ',') {
                    ++mAt;
                    continue;
                }
                if (mAt < mText.size() && mText[mAt] == ']') return ++mAt, true;
                return failAt("expected ',' or ']'");
            }
        }
        if (c == '"') {
            out.type = JsonValue::Type::String;
            return parseString(out.string);
        }
        if (literal("true")) return out.type = JsonValue::Type::Bool, out.boolean = true, true;
        if (literal("false")) return out.type = JsonValue::Type::Bool, out.boolean = false, true;
        if (literal("null")) return out.type = JsonValue::Type::Null, true;
        const char* begin = mText.c_str() + mAt;
        char* end = nullptr;
        out.number = std::strtod(begin, &end);
        if (end == begin) return failAt("expected a value");
        out.type = JsonValue::Type::Number;
        mAt += size_t(end - begin);
        return true;
    }

    const std::string& mText;
    size_t mAt = 0;
    std::string mError;
};

} // namespace detail

/// Parses `text` as one JSON value; false (with `error`) when it is not.
inline bool parseJson(const std::string& text, JsonValue& out, std::string& error) {
    out = JsonValue{};
    return detail::JsonParser(text).parseDocument(out, error);
}

} // namespace tessera::test
