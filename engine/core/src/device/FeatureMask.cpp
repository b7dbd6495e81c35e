#include "tessera/device/FeatureMask.h"

#include <array>

namespace tessera::device {
namespace {

struct Named {
    const char* name;
    bool DeviceFeatures::*flag;
};

// The user-facing names: the words --list-devices and the backends'
// "missing" lists use, not Vulkan's member names.
constexpr std::array<Named, 8> kFeatures = {{
    {"tessellation", &DeviceFeatures::tessellationShader},
    {"geometry", &DeviceFeatures::geometryShader},
    {"transform-feedback", &DeviceFeatures::transformFeedback},
    {"pipeline-statistics", &DeviceFeatures::pipelineStatistics},
    {"timestamps", &DeviceFeatures::timestamps},
    {"wireframe", &DeviceFeatures::fillModeNonSolid},
    {"vertex-stores", &DeviceFeatures::vertexStores},
    {"multi-draw-indirect", &DeviceFeatures::multiDrawIndirect},
}};

} // namespace

std::string featureMaskNames() {
    std::string out;
    for (const Named& f : kFeatures) out += (out.empty() ? "" : ", ") + std::string(f.name);
    return out;
}

Result<FeatureMask> parseFeatureMask(std::string_view list) {
    FeatureMask mask;
    if (list.empty()) return mask;
    for (bool more = true; more;) {
        // Every element between commas must be a name: "a,,b" and "a," are typos.
        const size_t comma = list.find(',');
        const std::string_view word = list.substr(0, comma);
        more = comma != std::string_view::npos;
        if (more) list.remove_prefix(comma + 1);
        bool known = false;
        for (size_t i = 0; i < kFeatures.size(); ++i) {
            if (word == kFeatures[i].name) {
                mask.bits |= 1u << i;
                known = true;
            }
        }
        if (!known)
            return fail("unknown feature \"", std::string(word), "\" (known: ", featureMaskNames(), ")");
    }
    return mask;
}

void applyFeatureMask(const FeatureMask& mask, DeviceFeatures& features) {
    for (size_t i = 0; i < kFeatures.size(); ++i)
        if (mask.bits & (1u << i)) features.*kFeatures[i].flag = false;
    if (!features.tessellationShader) features.maxTessellationLevel = 0;
}

} // namespace tessera::device
