#include "tessera/demo/FlagValues.h"

#include "tessera/cli/NumberList.h"
#include "tessera/cli/Validators.h"
#include "tessera/crowd/Crowd.h"

#include <cctype>
#include <cmath>
#include <cstdint>

namespace tessera::demo {

bool isObjFile(const std::string& path) {
    if (path.size() < 4) return false;
    std::string ext = path.substr(path.size() - 4);
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    return ext == ".obj";
}

Result<std::vector<uint32_t>> parseAgents(const std::string& text) {
    const cli::ListForm form{"--agents",
                             "a whole number of agents from 1 to " + std::to_string(crowd::Crowd::kMaxAgents) +
                                 " (a comma list with --bench crowd or crowd-sim)",
                             {}, 1, SIZE_MAX, ',', 1.0, double(crowd::Crowd::kMaxAgents)};
    auto counts = cli::parseNumberList<uint32_t>(text, form);
    if (!counts) return cli::expectedError(form, text);
    return counts;
}

Result<glm::vec3> parseColor(const std::string& text) {
    const cli::ListForm form{"--clear-color", "r,g,b with each in [0,1]", {}, 3, 3, ',', 0.0, 1.0};
    auto rgb = cli::parseNumberList<float>(text, form);
    if (!rgb) return cli::expectedError(form, text);
    return glm::vec3(rgb.value()[0], rgb.value()[1], rgb.value()[2]);
}

Result<glm::vec3> parseSun(const std::string& text) {
    const cli::ListForm form{"--sun",
                             "azimuth,elevation in degrees (azimuth from +X towards +Z, elevation 1 to 90)", {}, 2, 2};
    auto values = cli::parseNumberList<float>(text, form);
    if (!values || values.value()[1] < 1.0f || values.value()[1] > 90.0f) return cli::expectedError(form, text);
    const float azimuth = glm::radians(values.value()[0]);
    const float elevation = glm::radians(values.value()[1]);
    return glm::vec3(std::cos(elevation) * std::cos(azimuth), std::sin(elevation),
                     std::cos(elevation) * std::sin(azimuth));
}

Result<terrain::CraterSplat> parseSplat(const std::string& text) {
    const cli::ListForm form{"--splat", "x,z,radius[,depth] in metres with radius > 0 and depth >= 0", {}, 3, 4};
    auto values = cli::parseNumberList<float>(text, form);
    if (!values) return cli::expectedError(form, text);
    const std::vector<float>& v = values.value();
    if (v[2] <= 0.0f || (v.size() == 4 && v[3] < 0.0f)) return cli::expectedError(form, text);
    terrain::CraterSplat splat;
    splat.center = {v[0], v[1]};
    splat.radius = v[2];
    splat.profile = terrain::scaledCraterProfile(v[2]);
    if (v.size() == 4) splat.profile.depth = v[3];
    return splat;
}

Result<std::pair<float, std::optional<float>>> parseSweep(const std::string& flag, const std::string& text, float lo,
                                                         float hi) {
    const cli::ListForm form{flag, "a number from " + cli::formatNumber(lo) + " to " + cli::formatNumber(hi), {},
                             1, 2, ':', lo, hi};
    auto values = cli::parseNumberList<float>(text, form);
    if (!values) return values.error();
    std::pair<float, std::optional<float>> sweep{values.value()[0], std::nullopt};
    if (values.value().size() == 2) sweep.second = values.value()[1];
    return sweep;
}

} // namespace tessera::demo
