#include "tessera/core/JsonWriter.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <string>

namespace tessera {
namespace {

std::string scalar(auto v) {
    JsonWriter json;
    json.value(v);
    return json.str();
}

TEST(JsonWriter, WritesCompactNestedContainers) {
    JsonWriter json;
    json.beginObject();
    json.keyValue("a", 1);
    json.key("b");
    json.beginArray();
    json.value(true);
    json.value(false);
    json.null();
    json.endArray();
    json.key("c");
    json.beginObject();
    json.endObject();
    json.key("d");
    json.beginArray();
    json.endArray();
    EXPECT_FALSE(json.complete());
    json.endObject();
    EXPECT_TRUE(json.complete());
    EXPECT_EQ(json.str(), R"({"a":1,"b":[true,false,null],"c":{},"d":[]})");
}

TEST(JsonWriter, PrettyPrintsWithTwoSpaceIndent) {
    JsonWriter json(/*pretty=*/true);
    json.beginObject();
    json.keyValue("name", "terrain");
    json.key("ms");
    json.beginArray();
    json.value(1.5);
    json.value(2.0);
    json.endArray();
    json.key("empty");
    json.beginObject();
    json.endObject();
    json.endObject();
    EXPECT_EQ(json.str(), "{\n  \"name\": \"terrain\",\n  \"ms\": [\n    1.5,\n    2\n  ],\n"
                          "  \"empty\": {}\n}");
}

TEST(JsonWriter, EscapesQuotesBackslashesAndControlCharacters) {
    EXPECT_EQ(scalar(std::string_view("q\"b\\s/")), R"("q\"b\\s/")");
    EXPECT_EQ(scalar(std::string_view("a\nb\tc\r")), R"("a\u000ab\u0009c\u000d")");
    EXPECT_EQ(scalar(std::string_view("\x01\x1f\x7f", 3)), "\"\\u0001\\u001f\x7f\"");
    EXPECT_EQ(scalar(std::string_view("nul\0in", 6)), R"("nul\u0000in")");
    EXPECT_EQ(scalar(""), R"("")");
}

TEST(JsonWriter, PassesUtf8Through) {
    EXPECT_EQ(scalar("h\xC3\xA9llo \xE2\x9C\x93 \xF0\x9F\x8C\x8B"),
              "\"h\xC3\xA9llo \xE2\x9C\x93 \xF0\x9F\x8C\x8B\"");
}

TEST(JsonWriter, EscapesKeysToo) {
    JsonWriter json;
    json.beginObject();
    json.keyValue("a\"b", "c");
    json.endObject();
    EXPECT_EQ(json.str(), R"({"a\"b":"c"})");
}

TEST(JsonWriter, FormatsDoublesShortestRoundTrip) {
    EXPECT_EQ(scalar(1500.0), "1500");
    EXPECT_EQ(scalar(0.1), "0.1");
    EXPECT_EQ(scalar(1234.567), "1234.567");
    EXPECT_EQ(scalar(-2.5), "-2.5");
    EXPECT_EQ(scalar(1e21), "1e+21");
    EXPECT_EQ(scalar(1e-7), "1e-07");
    EXPECT_EQ(scalar(0.0), "0");
    EXPECT_EQ(scalar(1.0 / 3.0), "0.3333333333333333");
}

std::string fixed(double v, int decimals) {
    JsonWriter json;
    json.valueFixed(v, decimals);
    return json.str();
}

TEST(JsonWriter, FormatsFixedWithoutExponentOrTrailingZeros) {
    EXPECT_EQ(fixed(1500.0, 3), "1500");
    EXPECT_EQ(fixed(1.234, 3), "1.234");
    EXPECT_EQ(fixed(1.2, 3), "1.2");
    EXPECT_EQ(fixed(1e7, 3), "10000000");
    EXPECT_EQ(fixed(0.0025, 3), "0.003"); // Rounded (0.0025 is just above in binary).
    EXPECT_EQ(fixed(0.9025000000000001, 6), "0.9025");
    EXPECT_EQ(fixed(-0.0001, 3), "0");
    EXPECT_EQ(fixed(-2.5, 0), "-2");
    EXPECT_EQ(fixed(1e21, 2), "1000000000000000000000");
    EXPECT_EQ(fixed(std::numeric_limits<double>::max(), 30).size(), 309u);
    EXPECT_EQ(fixed(std::numeric_limits<double>::quiet_NaN(), 3), "null");
}

TEST(JsonWriter, WritesNonFiniteDoublesAsNull) {
    EXPECT_EQ(scalar(std::numeric_limits<double>::quiet_NaN()), "null");
    EXPECT_EQ(scalar(std::numeric_limits<double>::infinity()), "null");
    EXPECT_EQ(scalar(-std::numeric_limits<double>::infinity()), "null");
}

TEST(JsonWriter, FormatsIntegersExactly) {
    EXPECT_EQ(scalar(std::numeric_limits<int64_t>::min()), "-9223372036854775808");
    EXPECT_EQ(scalar(std::numeric_limits<uint64_t>::max()), "18446744073709551615");
    EXPECT_EQ(scalar(42), "42");
    EXPECT_EQ(scalar(uint32_t{7}), "7");
    EXPECT_EQ(scalar(int16_t{-3}), "-3");
    EXPECT_EQ(scalar(size_t{12}), "12");
}

TEST(JsonWriter, LiteralsAreStringsNotBools) {
    EXPECT_EQ(scalar("x"), R"("x")");
    EXPECT_EQ(scalar(std::string("y")), R"("y")");
    EXPECT_EQ(scalar(true), "true");
}

TEST(JsonWriter, TakeMovesTheDocumentOut) {
    JsonWriter json;
    json.beginArray();
    json.value(1);
    json.endArray();
    EXPECT_EQ(std::move(json).take(), "[1]");
}

TEST(JsonWriterDeathTest, AssertsOnMisuse) {
    EXPECT_DEBUG_DEATH(
        {
            JsonWriter json;
            json.beginObject();
            json.value(1);
        },
        "without key");
    EXPECT_DEBUG_DEATH(
        {
            JsonWriter json;
            json.beginObject();
            json.endArray();
        },
        "mismatch");
    EXPECT_DEBUG_DEATH(
        {
            JsonWriter json;
            json.endObject();
        },
        "without a matching begin");
    EXPECT_DEBUG_DEATH(
        {
            JsonWriter json;
            json.value(1);
            json.value(2);
        },
        "one root value");
}

} // namespace
} // namespace tessera
