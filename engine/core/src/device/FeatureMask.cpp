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
constexpr std::array<Named, 9> kFeatures = {{
    {"tessellation", &DeviceFeatures::tessellationShader},
    {"geometry", &DeviceFeatures::geometryShader},
    {"transform-feedback", &DeviceFeatures::transformFeedback},
    {"pipeline-statistics", &DeviceFeatures::pipelineStatistics},
    {"timestamps", &DeviceFeatures::timestamps},
    {"wireframe", &DeviceFeatures::fillModeNonSolid},
    {"vertex-stores", &DeviceFeatures::vertexStores},
    {"multi-draw-indirect", &DeviceFeatures::multiDrawIndirect},
    {"mesh-shader", &DeviceFeatures::meshShader},
}};

} // namespace

std::string featureMaskNames() {
    std::string out;
    for (const Named& f : kFeatures) out += (out.empty() ? "" : ", ") + std::string(f.name);
    return out;
}

std::optional<FeatureMask> featureNamed(std::string_view name) {
    for (size_t i = 0; i < kFeatures.size(); ++i)
        if (name == kFeatures[i].name) return FeatureMask{1u << i};
    return std::nullopt;
}

void applyFeatureMask(const FeatureMask& mask, DeviceFeatures& features) {
    for (size_t i = 0; i < kFeatures.size(); ++i)
        if (mask.bits & (1u << i)) features.*kFeatures[i].flag = false;
    if (!features.tessellationShader) features.maxTessellationLevel = 0;
    // The mesh-shader queries extend pipeline statistics: hiding either hides them.
    if (!features.pipelineStatistics) features.meshShaderQueries = false;
    // Hiding mesh shaders hides what only exists with them.
    if (!features.meshShader) {
        features.meshShaderQueries = false;
        features.maxMeshOutputVertices = features.maxMeshOutputPrimitives = 0;
        features.maxMeshWorkGroupInvocations = features.maxTaskPayloadSize = 0;
    }
}

} // namespace tessera::device
