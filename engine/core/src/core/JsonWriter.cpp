#include "tessera/core/JsonWriter.h"

#include <cassert>
#include <charconv>
#include <cmath>
#include <utility>

namespace tessera {

JsonWriter::JsonWriter(bool pretty) : mPretty(pretty) {}

std::string JsonWriter::take() && {
    assert(complete() && "take() before the document is complete");
    return std::move(mOut);
}

void JsonWriter::beginObject() { beginContainer(true, '{'); }
void JsonWriter::endObject() { endContainer(true, '}'); }
void JsonWriter::beginArray() { beginContainer(false, '['); }
void JsonWriter::endArray() { endContainer(false, ']'); }

void JsonWriter::key(std::string_view name) {
    assert(!mStack.empty() && mStack.back().isObject && "key() outside an object");
    assert(!mHaveKey && "key() twice without a value");
    // Misuse asserts in debug; in release it must not touch an empty stack.
    if (mStack.empty()) return;
    Container& top = mStack.back();
    if (!top.isEmpty) mOut.push_back(',');
    top.isEmpty = false;
    newlineAndIndent();
    writeString(name);
    mOut.push_back(':');
    if (mPretty) mOut.push_back(' ');
    mHaveKey = true;
}

void JsonWriter::value(std::string_view text) {
    beforeValue();
    writeString(text);
    afterValue();
}

void JsonWriter::value(const char* text) {
    assert(text != nullptr && "value(const char*) given null; use null()");
    value(std::string_view(text));
}

void JsonWriter::value(double number) {
    if (!std::isfinite(number)) {
        null();
        return;
    }
    // Shortest round-trip form: values read back bit-identical and integral
    // doubles print without a trailing ".0", so microsecond timestamps stay short.
    char buffer[32];
    auto [end, ec] = std::to_chars(buffer, buffer + sizeof(buffer), number);
    assert(ec == std::errc());
    writeToken(std::string_view(buffer, static_cast<size_t>(end - buffer)));
}

void JsonWriter::valueFixed(double number, int maxDecimals) {
    assert(maxDecimals >= 0 && maxDecimals <= 30);
    if (!std::isfinite(number)) {
        null();
        return;
    }
    // DBL_MAX has 309 integer digits in fixed notation.
    char buffer[350];
    auto [end, ec] = std::to_chars(buffer, buffer + sizeof(buffer), number, std::chars_format::fixed,
                                   maxDecimals);
    assert(ec == std::errc());
    std::string_view text(buffer, static_cast<size_t>(end - buffer));
    if (text.find('.') != std::string_view::npos) {
        while (text.back() == '0') text.remove_suffix(1);
        if (text.back() == '.') text.remove_suffix(1);
    }
    // A tiny negative value rounds to "-0"; write plain zero.
    if (text == "-0") text = "0";
    writeToken(text);
}

void JsonWriter::value(int64_t number) {
    char buffer[24];
    auto [end, ec] = std::to_chars(buffer, buffer + sizeof(buffer), number);
    assert(ec == std::errc());
    writeToken(std::string_view(buffer, static_cast<size_t>(end - buffer)));
}

void JsonWriter::value(uint64_t number) {
    char buffer[24];
    auto [end, ec] = std::to_chars(buffer, buffer + sizeof(buffer), number);
    assert(ec == std::errc());
    writeToken(std::string_view(buffer, static_cast<size_t>(end - buffer)));
}

void JsonWriter::value(bool flag) { writeToken(flag ? "true" : "false"); }

void JsonWriter::null() { writeToken("null"); }

void JsonWriter::beforeValue() {
    if (mStack.empty()) {
        assert(!mRootDone && "a JSON document holds one root value");
        return;
    }
    Container& top = mStack.back();
    if (top.isObject) {
        // key() already wrote the separator and indentation.
        assert(mHaveKey && "value inside an object without key()");
        mHaveKey = false;
        return;
    }
    if (!top.isEmpty) mOut.push_back(',');
    top.isEmpty = false;
    newlineAndIndent();
}

void JsonWriter::afterValue() {
    if (mStack.empty()) mRootDone = true;
}

void JsonWriter::beginContainer(bool isObject, char open) {
    beforeValue();
    mOut.push_back(open);
    mStack.push_back({isObject, true});
}

void JsonWriter::endContainer(bool isObject, char close) {
    assert(!mStack.empty() && "end without a matching begin");
    assert(mStack.back().isObject == isObject && "endObject/endArray mismatch");
    assert(!mHaveKey && "object closed after a key with no value");
    (void)isObject; // Only checked by the assert.
    if (mStack.empty()) return;
    bool wasEmpty = mStack.back().isEmpty;
    mStack.pop_back();
    // Empty containers stay on one line ("{}", "[]") even when pretty.
    if (!wasEmpty) newlineAndIndent();
    mOut.push_back(close);
    afterValue();
}

void JsonWriter::newlineAndIndent() {
    if (!mPretty) return;
    mOut.push_back('\n');
    mOut.append(2 * mStack.size(), ' ');
}

void JsonWriter::writeString(std::string_view text) {
    static constexpr char kHex[] = "0123456789abcdef";
    mOut.push_back('"');
    // Copy runs of plain bytes in one append; most names need no escaping.
    size_t runStart = 0;
    for (size_t i = 0; i < text.size(); ++i) {
        auto byte = static_cast<unsigned char>(text[i]);
        if (byte >= 0x20 && byte != '"' && byte != '\\') continue;
        mOut.append(text.substr(runStart, i - runStart));
        runStart = i + 1;
        if (byte == '"' || byte == '\\') {
            mOut.push_back('\\');
            mOut.push_back(static_cast<char>(byte));
        } else {
            mOut.append("\\u00");
            mOut.push_back(kHex[byte >> 4]);
            mOut.push_back(kHex[byte & 0xF]);
        }
    }
    mOut.append(text.substr(runStart));
    mOut.push_back('"');
}

void JsonWriter::writeToken(std::string_view text) {
    beforeValue();
    mOut.append(text);
    afterValue();
}

} // namespace tessera
