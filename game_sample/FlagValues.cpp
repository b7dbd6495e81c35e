#include "FlagValues.h"

#include "tessera/cli/Validators.h"
#include "tessera/crowd/Crowd.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace tessera::demo {

bool isObjFile(const std::string& path) {
    if (path.size() < 4) return false;
    std::string ext = path.substr(path.size() - 4);
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    return ext == ".obj";
}

Result<std::vector<uint32_t>> parseAgents(const std::string& text) {
    const Error bad = fail("--agents expects a whole number of agents from 1 to ",
                           std::to_string(crowd::Crowd::kMaxAgents), " (a comma list with --bench crowd or crowd-sim), got \"",
                           text, "\"");
    std::vector<uint32_t> counts;
    std::stringstream stream(text);
    std::string part;
    while (std::getline(stream, part, ',')) {
        uint64_t value = 0;
        auto [end, ec] = std::from_chars(part.data(), part.data() + part.size(), value);
        if (ec != std::errc() || end != part.data() + part.size() || value < 1 || value > crowd::Crowd::kMaxAgents)
            return bad;
        counts.push_back(uint32_t(value));
    }
    if (counts.empty() || text.back() == ',') return bad;
    return counts;
}

Result<glm::vec3> parseColor(const std::string& text) {
    glm::vec3 color{};
    std::stringstream stream(text);
    std::string part;
    int n = 0;
    while (std::getline(stream, part, ',')) {
        char* end = nullptr;
        const float v = std::strtof(part.c_str(), &end);
        if (n >= 3 || part.empty() || *end != '\0' || !std::isfinite(v) || v < 0.0f || v > 1.0f)
            return fail("--clear-color expects r,g,b with each in [0,1], got \"", text, "\"");
        color[n++] = v;
    }
    if (n != 3) return fail("--clear-color expects r,g,b with each in [0,1], got \"", text, "\"");
    return color;
}

Result<glm::vec3> parseSun(const std::string& text) {
    const auto bad = [&] {
        return fail("--sun expects azimuth,elevation in degrees (azimuth from +X towards +Z, elevation 1 to 90), got \"",
                    text, "\"");
    };
    float values[2] = {};
    std::stringstream stream(text);
    std::string part;
    int n = 0;
    while (std::getline(stream, part, ',')) {
        char* end = nullptr;
        const float v = std::strtof(part.c_str(), &end);
        if (n >= 2 || part.empty() || *end != '\0' || !std::isfinite(v)) return bad();
        values[n++] = v;
    }
    if (n != 2 || values[1] < 1.0f || values[1] > 90.0f) return bad();
    const float azimuth = glm::radians(values[0]);
    const float elevation = glm::radians(values[1]);
    return glm::vec3(std::cos(elevation) * std::cos(azimuth), std::sin(elevation),
                     std::cos(elevation) * std::sin(azimuth));
}

Result<terrain::CraterSplat> parseSplat(const std::string& text) {
    std::vector<float> values;
    std::stringstream stream(text);
    std::string part;
    bool numbers = true;
    while (std::getline(stream, part, ',')) {
        char* end = nullptr;
        const float v = std::strtof(part.c_str(), &end);
        numbers = numbers && !part.empty() && *end == '\0' && std::isfinite(v);
        values.push_back(v);
    }
    const bool shaped = numbers && (values.size() == 3 || values.size() == 4);
    if (!shaped || values[2] <= 0.0f || (values.size() == 4 && values[3] < 0.0f))
        return fail("--splat expects x,z,radius[,depth] in metres with radius > 0 and depth >= 0, got \"", text, "\"");
    terrain::CraterSplat splat;
    splat.center = {values[0], values[1]};
    splat.radius = values[2];
    splat.profile = terrain::scaledCraterProfile(values[2]);
    if (values.size() == 4) splat.profile.depth = values[3];
    return splat;
}

Result<std::pair<float, std::optional<float>>> parseSweep(const std::string& flag, const std::string& text, float lo,
                                                         float hi) {
    const size_t colon = text.find(':');
    std::string parts[2] = {text.substr(0, colon), colon == std::string::npos ? std::string() : text.substr(colon + 1)};
    const CLI::Validator inRange = cli::number(lo, hi);
    for (int i = 0; i < (colon == std::string::npos ? 1 : 2); ++i)
        if (std::string why = inRange(parts[i]); !why.empty()) return fail(flag, " ", why);
    std::pair<float, std::optional<float>> sweep{std::strtof(parts[0].c_str(), nullptr), std::nullopt};
    if (colon != std::string::npos) sweep.second = std::strtof(parts[1].c_str(), nullptr);
    return sweep;
}

} // namespace tessera::demo
