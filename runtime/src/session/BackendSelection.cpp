#include "tessera/runtime/BackendSelection.h"

#include "session/SelectedBackend.h"

#include "tessera/runtime/Reporter.h"
#include "tessera/core/Log.h"

#include <cstdio>
#include <optional>

namespace tessera::runtime {

Status listBackends(const Options& options) {
    auto loader = pluginLoaderFor(options);
    backend::BackendRegistry registry;
    for (const auto& error : loader.loadAll(registry)) reporterFor(options).warning(error);

    std::optional<device::DeviceFeatures> deviceFeatures;
    if (auto created = makeInstance(options); created) {
        auto physical = created.value()->selectDevice(options.device);
        if (!physical) return physical.error();
        std::printf("device: %s (%s)\n\n", physical->features.deviceName.c_str(), gpu::deviceTypeName(physical->type));
        deviceFeatures = physical->features;
        device::applyFeatureMask(options.hiddenFeatures, *deviceFeatures);
    } else {
        std::printf("device: none (%s)\n\n", created.error().message.c_str());
    }

    const device::DeviceFeatures* features = deviceFeatures ? &*deviceFeatures : nullptr;
    std::printf("%-11s %-9s %-10s %-4s %-4s %-7s %-4s %-6s %s\n", "backend", "status", "tess", "xfb", "geom", "compute",
                "mesh", "max tf", "description");
    for (const auto& name : registry.names()) {
        auto backend = registry.create(name);
        if (!backend) continue;
        auto caps = backend.value()->capabilities(features);
        const bool runnable = caps.supported() && (features || !caps.requiresGpu);
        std::printf("%-11s %-9s %-10s %-4s %-4s %-7s %-4s %-6.2f %s\n", name.c_str(), runnable ? "ok" : "no",
                    backend::toString(caps.tessellation), caps.usesTransformFeedback ? "yes" : "-",
                    caps.usesGeometryShaders ? "yes" : "-", caps.usesCompute ? "yes" : "-",
                    caps.usesMeshShaders ? "yes" : "-", caps.maxTessFactor, caps.description.c_str());
        if (!caps.missing.empty()) std::printf("%-11s missing: %s\n", "", joinMissing(caps).c_str());
        std::printf("%-11s from %s\n", "", registry.sourceOf(name).c_str());
    }
    return {};
}

Status listDevices(const Options& options) {
    auto instance = makeInstance(options);
    if (!instance) return instance.error();
    auto chosen = instance.value()->selectDevice(options.device);
    for (const auto& d : instance.value()->devices()) {
        device::DeviceFeatures f = d.features;
        device::applyFeatureMask(options.hiddenFeatures, f);
        std::printf("%u: %s (%s) driver %s %s%s\n   tessellation %s (max %u), geometry %s, transform feedback %s, "
                    "pipeline statistics %s, timestamps %s\n",
                    d.index, f.deviceName.c_str(), gpu::deviceTypeName(d.type), f.driverName.c_str(), f.driverInfo.c_str(),
                    chosen && chosen->index == d.index ? "  [default]" : "", f.tessellationShader ? "yes" : "no",
                    f.maxTessellationLevel, f.geometryShader ? "yes" : "no", f.transformFeedback ? "yes" : "no",
                    f.pipelineStatistics ? "yes" : "no", f.timestamps ? "yes" : "no");
        if (f.meshShader)
            std::printf("   mesh shaders yes (%u vertices, %u primitives, %u invocations a workgroup; task payload %u "
                        "bytes; queries %s)\n",
                        f.maxMeshOutputVertices, f.maxMeshOutputPrimitives, f.maxMeshWorkGroupInvocations,
                        f.maxTaskPayloadSize, f.meshShaderQueries ? "yes" : "no");
        else
            std::printf("   mesh shaders no\n");
    }
    return {};
}

uint64_t validationMessages() { return gpu::Instance::validationMessageCount(); }

} // namespace tessera::runtime
