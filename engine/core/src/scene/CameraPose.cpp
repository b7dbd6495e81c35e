#include "tessera/scene/CameraPose.h"

#include <array>
#include <charconv>
#include <cmath>
#include <system_error>

namespace tessera::scene {
namespace {

constexpr const char* kFieldNames[] = {"x", "y", "z", "yaw", "pitch"};
constexpr size_t kFieldCount = 5;

std::string_view trim(std::string_view s) {
    constexpr std::string_view kSpace = " \t";
    size_t first = s.find_first_not_of(kSpace);
    if (first == std::string_view::npos) return {};
    size_t last = s.find_last_not_of(kSpace);
    return s.substr(first, last - first + 1);
}

std::string quoted(std::string_view s) {
    std::string out = "\"";
    out.append(s);
    out.append("\"");
    return out;
}

/// Parses one whole field as a finite float, or says why it is not one.
Result<float> parseNumber(std::string_view field, size_t index) {
    std::string_view digits = field;
    // from_chars rejects a leading '+', which people type ("+10"); allow it
    // once, but not "+-1" or a bare "+".
    if (digits.size() > 1 && digits[0] == '+' && digits[1] != '-' && digits[1] != '+') {
        digits.remove_prefix(1);
    }
    float value = 0.0f;
    auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    const std::string name = kFieldNames[index];
    if (ec == std::errc::result_out_of_range) {
        return fail("--camera: ", name, " = ", quoted(field), " is out of range");
    }
    if (ec != std::errc{} || end != digits.data() + digits.size()) {
        return fail("--camera: ", name, " = ", quoted(field), " is not a number");
    }
    // from_chars accepts "nan" and "inf", which would poison every matrix.
    if (!std::isfinite(value)) {
        return fail("--camera: ", name, " = ", quoted(field), " is not a finite number");
    }
    return value;
}

} // namespace

Result<CameraPose> parseCameraPose(std::string_view text) {
    std::array<std::string_view, kFieldCount> fields;
    size_t count = 0;
    size_t start = 0;
    for (;;) {
        size_t comma = text.find(',', start);
        std::string_view field = text.substr(start, comma == std::string_view::npos
                                                        ? std::string_view::npos
                                                        : comma - start);
        if (count < kFieldCount) fields[count] = trim(field);
        ++count;
        if (comma == std::string_view::npos) break;
        start = comma + 1;
    }
    if (count != kFieldCount) {
        return fail("--camera expects x,y,z,yaw,pitch (5 numbers), got ", quoted(text));
    }

    std::array<float, kFieldCount> values{};
    for (size_t i = 0; i < kFieldCount; ++i) {
        if (fields[i].empty()) {
            return fail("--camera: ", kFieldNames[i], " is missing in ", quoted(text),
                        " (expects x,y,z,yaw,pitch)");
        }
        Result<float> number = parseNumber(fields[i], i);
        if (!number) return number.error();
        values[i] = number.value();
    }
    CameraPose pose;
    pose.position = glm::vec3(values[0], values[1], values[2]);
    pose.yaw = glm::radians(values[3]);
    pose.pitch = glm::radians(values[4]);
    return pose;
}

std::string formatCameraPose(const CameraPose& pose) {
    const float values[kFieldCount] = {pose.position.x, pose.position.y, pose.position.z,
                                       glm::degrees(pose.yaw), glm::degrees(pose.pitch)};
    std::string out;
    for (size_t i = 0; i < kFieldCount; ++i) {
        // to_chars gives the shortest text that reads back to the same float,
        // independent of locale.
        char buffer[32];
        auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, values[i]);
        if (i > 0) out.push_back(',');
        out.append(buffer, ec == std::errc{} ? end : buffer);
    }
    return out;
}

} // namespace tessera::scene
