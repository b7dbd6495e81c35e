#pragma once
/// @file JsonWriter.h
/// A small streaming JSON writer that appends to a std::string.
///
/// Used by every file Tessera writes for tools (profiler traces, benchmark
/// reports). It writes exactly what it is told, in order, with no DOM, so a
/// trace of a million events costs one string and no allocations per event
/// beyond the string's growth.
///
/// Rules:
/// - Inside an object every value is preceded by key(); inside an array it is
///   not. Breaking this, or closing the wrong container, is a programming
///   error and asserts.
/// - One root value per writer.
/// - Strings are written as UTF-8: `"` and `\` are escaped, bytes below 0x20
///   become `\u00XX`, every other byte (UTF-8 multi-byte sequences included) is
///   copied unchanged. The writer does not validate UTF-8.
/// - Doubles use std::to_chars' shortest round-trip form (1500.0 -> `1500`,
///   0.1 -> `0.1`, 1e21 -> `1e+21`), or fixed notation with valueFixed();
///   NaN and infinities, which JSON cannot express, are written as `null`.
///
/// @code
/// JsonWriter json(/*pretty=*/true);
/// json.beginObject();
/// json.keyValue("name", "terrain");
/// json.key("ms");
/// json.beginArray(); json.value(1.5); json.value(2.0); json.endArray();
/// json.endObject();
/// // json.str() == "{\n  \"name\": \"terrain\",\n  \"ms\": [\n    1.5,\n    2\n  ]\n}"
/// @endcode

#include <cstdint>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace tessera {

class JsonWriter {
public:
    /// @param pretty  Newline and two-space indentation per nesting level, and
    ///                a space after each `:`. Compact (no whitespace) otherwise.
    explicit JsonWriter(bool pretty = false);

    void beginObject();
    void endObject();
    void beginArray();
    void endArray();

    /// Writes an object member's name; the next call must write its value.
    void key(std::string_view name);

    /// Writes a string value (escaped as described in the file comment).
    void value(std::string_view text);
    /// Writes a string value; exists so that literals do not convert to bool.
    /// `text` must not be null.
    void value(const char* text);
    /// Writes a number in shortest round-trip form; NaN/Inf become `null`.
    void value(double number);
    /// Writes a number in fixed notation rounded to at most `maxDecimals`
    /// (0..30) decimals, trailing zeros dropped: never an exponent, so
    /// readers with hand-written number parsers (trace viewers reading
    /// timestamps) and people get `10000000` rather than `1e+07`.
    /// NaN/Inf become `null`.
    void valueFixed(double number, int maxDecimals);
    void value(int64_t number);
    void value(uint64_t number);
    void value(bool flag);
    /// Any other integer type (int, uint32_t, size_t, ...), written exactly.
    /// Without this, `value(42)` would be ambiguous between the overloads above.
    template <class T>
        requires(std::is_integral_v<T> && !std::is_same_v<T, bool> && !std::is_same_v<T, char>)
    void value(T number) {
        if constexpr (std::is_signed_v<T>) {
            value(static_cast<int64_t>(number));
        } else {
            value(static_cast<uint64_t>(number));
        }
    }
    /// Writes `null`.
    void null();

    /// key(name) followed by value(v).
    template <class T>
    void keyValue(std::string_view name, T&& v) {
        key(name);
        value(std::forward<T>(v));
    }

    /// The document so far. Complete once complete() is true.
    const std::string& str() const { return mOut; }
    /// Moves the finished document out (asserts complete()), avoiding a copy
    /// of a large trace. The writer must not be used afterwards.
    std::string take() &&;
    /// True when one root value has been written and every container closed.
    bool complete() const { return mRootDone && mStack.empty(); }

private:
    struct Container {
        bool isObject;
        bool isEmpty;
    };

    void beforeValue();
    void afterValue();
    void beginContainer(bool isObject, char open);
    void endContainer(bool isObject, char close);
    void newlineAndIndent();
    void writeString(std::string_view text);
    void writeToken(std::string_view text);

    std::string mOut;
    std::vector<Container> mStack;
    bool mPretty = false;
    bool mHaveKey = false;
    bool mRootDone = false;
};

} // namespace tessera
